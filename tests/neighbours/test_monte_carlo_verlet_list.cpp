// The Monte Carlo neighbour structures stay exact under long sequences of random moves:
// MobileCells keeps every particle in the right cell; MonteCarloVerletList keeps every pair
// closer than the cutoff listed (both ways), through local re-listings and full rebuilds.
#include "core/random.hpp"
#include "neighbours/mobile_cells.hpp"
#include "neighbours/monte_carlo_verlet_list.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

using namespace cmp;
using neighbours::MobileCells;
using neighbours::MonteCarloVerletList;

namespace {
mesh::VertexMatrix random_points_in_cube(int n, double side, Random& rng) {
  mesh::VertexMatrix x(n, 3);
  for (int i = 0; i < n; ++i) x.row(i) << rng.uniform(0, side), rng.uniform(0, side), rng.uniform(0, side);
  return x;
}

void check_cells(const MobileCells& cells, const mesh::VertexMatrix& x) {
  std::set<int> seen;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const int id = static_cast<int>(i);
    REQUIRE(cells.cell_of_particle(id) == cells.cell_of(x.row(i)));
    const int slot = cells.slot_of_particle(id);
    REQUIRE(cells.ids()[slot] == id);
    REQUIRE(cells.xs()[slot] == static_cast<float>(x(i, 0)));
    REQUIRE(cells.zs()[slot] == static_cast<float>(x(i, 2)));
    seen.insert(id);
  }
  CHECK(seen.size() == static_cast<std::size_t>(x.rows()));
}

void check_list(const MonteCarloVerletList& list, const mesh::VertexMatrix& x, double cutoff) {
  const int n = static_cast<int>(x.rows());
  std::vector<std::set<int>> partners(n);
  for (int i = 0; i < n; ++i) {
    const int* ids = list.partner_ids() + list.begin(i);
    for (int k = 0; k < list.padded_count(i); ++k) {
      if (k >= list.count(i)) {
        REQUIRE(ids[k] == n);  // padding points at the far-away sentinel
      } else {
        partners[i].insert(ids[k]);
      }
    }
    REQUIRE(list.xs()[i] == static_cast<float>(x(i, 0)));
  }
  long close_pairs = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      REQUIRE(partners[i].count(j) == partners[j].count(i));  // symmetric
      if ((x.row(i) - x.row(j)).norm() < cutoff) {
        ++close_pairs;
        REQUIRE(partners[i].count(j) == 1);
      }
    }
  CHECK(close_pairs > 0);
}
}  // namespace

TEST_CASE("MobileCells follow random moves", "[neighbours][monte-carlo]") {
  Random rng(5);
  const double side = 10, cutoff = 1.3;
  mesh::VertexMatrix x = random_points_in_cube(400, side, rng);
  MobileCells cells(Eigen::Vector3d::Zero(), side, cutoff);
  cells.assign(x);
  CHECK(cells.cells_per_axis() == 7);
  for (int move = 0; move < 20000; ++move) {
    const int i = static_cast<int>(rng.below(400));
    Eigen::Vector3d p = x.row(i);
    for (int k = 0; k < 3; ++k) p[k] = std::clamp(p[k] + rng.uniform(-0.8, 0.8), 0.0, side);
    x.row(i) = p;
    cells.move(i, p);
  }
  check_cells(cells, x);
  // Crowd one cell past its capacity: the grid grows and stays consistent.
  for (int i = 0; i < 100; ++i) {
    x.row(i) << 0.1 + 0.001 * i, 0.1, 0.1;
    cells.move(i, x.row(i));
  }
  check_cells(cells, x);
  CHECK(cells.capacity() >= 100);
}

TEST_CASE("MonteCarloVerletList lists every close pair through moves and re-listings", "[neighbours][monte-carlo]") {
  Random rng(9);
  const double side = 12, cutoff = 1.5, skin = 0.6;
  mesh::VertexMatrix x = random_points_in_cube(500, side, rng);
  MobileCells cells(Eigen::Vector3d::Zero(), side, cutoff);
  cells.assign(x);
  MonteCarloVerletList list(cutoff, skin);
  list.build(x, cells);
  check_list(list, x, cutoff);
  for (int move = 0; move < 30000; ++move) {
    const int i = static_cast<int>(rng.below(500));
    // Mostly small steps (inside the skin), some large ones (re-listing).
    const double step = move % 7 == 0 ? 1.0 : 0.1;
    Eigen::Vector3d p = x.row(i);
    for (int k = 0; k < 3; ++k) p[k] = std::clamp(p[k] + rng.uniform(-step, step), 0.0, side);
    x.row(i) = p;
    cells.move(i, p);
    list.move(i, x, cells);
    if (move % 10000 == 0) check_list(list, x, cutoff);
  }
  check_list(list, x, cutoff);
  CHECK(list.relists() > 1000);
}

TEST_CASE("MonteCarloVerletList refuses a skin the cell stencil cannot reach", "[neighbours][monte-carlo]") {
  CHECK_THROWS_AS(MonteCarloVerletList(1.0, 0.7), UsageError);
  CHECK_NOTHROW(MonteCarloVerletList(1.0, 0.6));
}
