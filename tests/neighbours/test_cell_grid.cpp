#include "neighbours/cell_grid.hpp"

#include "core/errors.hpp"
#include "neighbours_test_support.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace cmp::neighbours;
using cmp::mesh::VertexMatrix;
namespace nt = cmp::neighbours::testing;

namespace {
// Every pair the grid reports, in brute-force form, sorted; counts pairs reported twice.
std::vector<nt::Pair> grid_pairs(const CellGrid& grid, const VertexMatrix& X, long& repeated) {
  std::vector<nt::Pair> pairs;
  grid.for_each_pair(X, [&](int i, int j, const Eigen::Vector3d& d, double r2) { pairs.push_back(nt::canonical(i, j, d, r2)); });
  std::sort(pairs.begin(), pairs.end());
  repeated = 0;
  for (std::size_t k = 1; k < pairs.size(); ++k) repeated += !(pairs[k - 1] < pairs[k]);
  return pairs;
}

void check_against_brute_force(const CellGrid& grid, const VertexMatrix& X) {
  const auto expected = nt::brute_force_pairs(X, grid.box(), grid.cutoff());
  long repeated = 0;
  const auto found = grid_pairs(grid, X, repeated);
  CHECK(repeated == 0);
  REQUIRE(found.size() == expected.size());
  long wrong_pair = 0, wrong_d = 0, wrong_r2 = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    wrong_pair += found[k].i != expected[k].i || found[k].j != expected[k].j;
    wrong_d += found[k].d != expected[k].d;  // the same arithmetic: bit for bit
    wrong_r2 += std::abs(found[k].r2 - expected[k].r2) > 1e-15 * expected[k].r2;
  }
  CHECK(wrong_pair == 0);
  CHECK(wrong_d == 0);
  CHECK(wrong_r2 == 0);
}

void check_invariants(const CellGrid& grid, const VertexMatrix& X) {
  const auto& start = grid.cell_start();
  const auto& sorted = grid.sorted_indices();
  REQUIRE(static_cast<int>(start.size()) == grid.cell_count() + 1);
  CHECK(start.front() == 0);
  CHECK(start.back() == X.rows());
  std::vector<int> seen(X.rows(), 0);
  long misplaced = 0, unordered = 0;
  for (int c = 0; c < grid.cell_count(); ++c)
    for (int k = start[c]; k < start[c + 1]; ++k) {
      misplaced += grid.cell_of(X.row(sorted[k]).transpose()) != c || grid.cell_of_particle(sorted[k]) != c;
      unordered += k > start[c] && sorted[k - 1] > sorted[k];
      ++seen[sorted[k]];
    }
  CHECK(misplaced == 0);
  CHECK(unordered == 0);
  CHECK(std::count(seen.begin(), seen.end(), 1) == X.rows());
}
}  // namespace

TEST_CASE("CellGrid cells per axis: floor(L / cutoff), a margin at exact multiples, 1 at least", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 10, 3.5, 0.2;
  box.periodic = {true, true, false};
  CHECK(CellGrid(box, 1.0).cells_per_axis() == Eigen::Vector3i(9, 3, 1));  // 10 = 10 x 1.0 exactly: 9
  CHECK(CellGrid(box, 0.9).cells_per_axis() == Eigen::Vector3i(11, 3, 1));
  CHECK(CellGrid(box, 1.75).cells_per_axis() == Eigen::Vector3i(5, 1, 1));  // cutoff = L_y / 2: one periodic cell
  CHECK(CellGrid(box, 1.7).cells_per_axis() == Eigen::Vector3i(5, 2, 1));
  CHECK(CellGrid(box, 1.0).cell_count() == 27);
  CHECK(CellGrid(box, 1.0, Eigen::Vector3i(2, 1, 1)).cells_per_axis() == Eigen::Vector3i(2, 1, 1));
}

TEST_CASE("CellGrid rejects what would be wrong", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 4, 3, 5;
  box.periodic = {false, true, false};
  CHECK_THROWS_AS(CellGrid(box, 1.6), cmp::UsageError);  // > L_y / 2 along a periodic axis
  CHECK_NOTHROW(CellGrid(box, 1.5));
  CHECK_THROWS_AS(CellGrid(box, 0.0), cmp::UsageError);
  CHECK_THROWS_AS(CellGrid(box, -1.0), cmp::UsageError);
  CHECK_THROWS_AS(CellGrid(box, NAN), cmp::UsageError);
  CHECK_THROWS_AS(CellGrid(box, 1.0, Eigen::Vector3i(4, 1, 1)), cmp::UsageError);  // 4 cells of 1 < 1 (1 + margin)
  CHECK_THROWS_AS(CellGrid(box, 1.0, Eigen::Vector3i(0, 1, 1)), cmp::UsageError);
  Box negative = box;
  negative.lengths[0] = -1;
  CHECK_THROWS_AS(CellGrid(negative, 1.0), cmp::UsageError);

  CellGrid grid(box, 1.0);
  VertexMatrix X = nt::random_points(10, box, 1);
  grid.build(X);
  VertexMatrix fewer = X.topRows(9);
  CHECK_THROWS_AS(grid.for_each_pair(fewer, [](int, int, const Eigen::Vector3d&, double) {}), cmp::UsageError);
  X(3, 1) = NAN;
  CHECK_THROWS_AS(grid.build(X), cmp::ComputationError);
}

TEST_CASE("CellGrid stencil: distinct cells, also with 1 and 2 cells along periodic axes", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 4, 4, 4;
  box.periodic = {true, true, false};
  for (const Eigen::Vector3i& cells : {Eigen::Vector3i(3, 3, 3), Eigen::Vector3i(2, 2, 2), Eigen::Vector3i(1, 2, 3),
                                      Eigen::Vector3i(1, 1, 1)}) {
    const CellGrid grid(box, 1.0, cells);
    for (int c = 0; c < grid.cell_count(); ++c) {
      std::multiset<int> stencil;
      grid.for_each_stencil_cell(c, [&](int other) { stencil.insert(other); });
      CHECK(std::set<int>(stencil.begin(), stencil.end()).size() == stencil.size());
      CHECK(stencil.count(c) == 1);
      // x and y periodic: min(n, 3) each; z not: 2 at the faces, 3 inside (or 1 if one cell)
      const int z = c / (cells[0] * cells[1]);
      const int nz = cells[2] == 1 ? 1 : (z == 0 || z == cells[2] - 1) ? 2 : 3;
      CHECK(static_cast<int>(stencil.size()) == std::min(cells[0], 3) * std::min(cells[1], 3) * nz);
    }
  }
}

TEST_CASE("CellGrid finds exactly the brute-force pairs for every box, periodicity and cutoff", "[neighbours][cell_grid]") {
  // Lengths 4, 3, 5: cutoffs from 0.4 (10 cells) to 1.5 (one periodic cell along y).
  std::uint64_t seed = 1;
  for (int flags = 0; flags < 8; ++flags)
    for (double cutoff : {0.4, 0.9, 1.4, 1.5}) {
      Box box;
      box.lower << -1.5, 2.0, 0.25;
      box.lengths << 4, 3, 5;
      box.periodic = {(flags & 1) != 0, (flags & 2) != 0, (flags & 4) != 0};
      const CellGrid probe(box, cutoff);
      INFO("periodic " << box.periodic[0] << box.periodic[1] << box.periodic[2] << " cutoff " << cutoff << " cells "
                       << probe.cells_per_axis().transpose());
      for (double outside : {0.0, 0.3}) {
        const VertexMatrix X = nt::random_points(300, box, seed++, outside);
        CellGrid grid(box, cutoff);
        grid.build(X);
        check_invariants(grid, X);
        check_against_brute_force(grid, X);
      }
    }
}

TEST_CASE("CellGrid with chosen coarse cells gives the same pairs", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 4, 4, 4;
  box.periodic = {true, true, true};
  const VertexMatrix X = nt::random_points(500, box, 77, 0.2);
  for (const Eigen::Vector3i& cells : {Eigen::Vector3i(1, 1, 1), Eigen::Vector3i(2, 2, 2), Eigen::Vector3i(1, 2, 3),
                                      Eigen::Vector3i(3, 3, 3)}) {
    INFO("cells " << cells.transpose());
    CellGrid grid(box, 1.2, cells);
    grid.build(X);
    check_against_brute_force(grid, X);
  }
}

TEST_CASE("CellGrid with points exactly on the box faces and the cell boundaries", "[neighbours][cell_grid]") {
  // A lattice of spacing 0.5 from lower to lower + L inclusive: points on every face and on
  // every cell boundary (cells 1.5 wide); distances sqrt(k)/2 never equal the cutoff 1.2.
  for (int flags : {0, 7, 5}) {
    Box box;
    box.lower << -2, -1, 0;
    box.lengths << 4.5, 3, 3;
    box.periodic = {(flags & 1) != 0, (flags & 2) != 0, (flags & 4) != 0};
    VertexMatrix X(10 * 7 * 7, 3);
    int n = 0;
    for (int i = 0; i <= 9; ++i)
      for (int j = 0; j <= 6; ++j)
        for (int k = 0; k <= 6; ++k) X.row(n++) << -2 + 0.5 * i, -1 + 0.5 * j, 0.5 * k;
    CellGrid grid(box, 1.2, Eigen::Vector3i(3, 2, 2));
    grid.build(X);
    check_invariants(grid, X);
    check_against_brute_force(grid, X);
    CHECK(grid.cell_of(Eigen::Vector3d(2.5, 0, 0)) == (box.periodic[0] ? 0 : 2));  // upper x face, y = z = 0: cell (x, 0, 0)
    if (box.periodic[0]) {  // x = -2 and x = 2.5 are one point: at distance 0
      int zero = 0;
      grid.for_each_pair(X, [&](int, int, const Eigen::Vector3d&, double r2) { zero += r2 == 0; });
      CHECK(zero > 0);
    }
  }
}

TEST_CASE("CellGrid in 2D: a box of zero height, one layer of cells", "[neighbours][cell_grid]") {
  for (int flags = 0; flags < 4; ++flags) {
    const Box box = make_planar_box(Eigen::Vector2d(1, -3), Eigen::Vector2d(7, 5), flags & 1, flags & 2);
    VertexMatrix X = nt::random_points(600, box, 100 + flags, 0.2);
    CHECK((X.col(2).array() == 0).all());
    CellGrid grid(box, 0.8);
    CHECK(grid.cells_per_axis() == Eigen::Vector3i(8, 6, 1));
    grid.build(X);
    check_invariants(grid, X);
    check_against_brute_force(grid, X);
  }
}

TEST_CASE("CellGrid::for_each_neighbour of query points equals brute force", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 5, 5, 3;
  box.periodic = {true, false, true};
  const VertexMatrix X = nt::random_points(500, box, 5, 0.1);
  CellGrid grid(box, 1.1);
  grid.build(X);
  const VertexMatrix queries = nt::random_points(50, box, 6, 0.5);
  for (int q = 0; q < queries.rows(); ++q) {
    const Eigen::Vector3d p = queries.row(q).transpose();
    std::vector<int> found, expected;
    grid.for_each_neighbour(X, p, [&](int j, const Eigen::Vector3d& d, double r2) {
      found.push_back(j);
      CHECK(d == box.minimum_image(p - X.row(j).transpose()));
      CHECK(r2 < 1.1 * 1.1);
    });
    for (int j = 0; j < X.rows(); ++j)
      if (box.minimum_image(p - X.row(j).transpose()).norm() < 1.1) expected.push_back(j);
    std::sort(found.begin(), found.end());
    CHECK(found == expected);
  }
  int self = 0;  // a particle's own position finds itself at r2 = 0
  grid.for_each_neighbour(X, X.row(7).transpose(), [&](int j, const Eigen::Vector3d&, double r2) { self += j == 7 && r2 == 0; });
  CHECK(self == 1);
}

TEST_CASE("CellGrid rebuilds: a second build replaces the first", "[neighbours][cell_grid]") {
  Box box;
  box.lengths << 3, 3, 3;
  CellGrid grid(box, 1.0);
  grid.build(nt::random_points(300, box, 8));
  const VertexMatrix X = nt::random_points(120, box, 9);
  grid.build(X);
  CHECK(grid.particle_count() == 120);
  check_invariants(grid, X);
  check_against_brute_force(grid, X);
  grid.build(VertexMatrix(0, 3));
  int calls = 0;
  grid.for_each_pair(VertexMatrix(0, 3), [&](int, int, const Eigen::Vector3d&, double) { ++calls; });
  CHECK(calls == 0);
}
