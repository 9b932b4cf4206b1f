#include "neighbours/neighbour_list.hpp"

#include "core/errors.hpp"
#include "neighbours_test_support.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

using namespace cmp::neighbours;
using cmp::mesh::VertexMatrix;
namespace nt = cmp::neighbours::testing;

namespace {
// The full rows brute force gives for radius r: row i = every j != i closer than r, ascending.
std::vector<std::vector<int>> brute_force_rows(const VertexMatrix& X, const Box& box, double r) {
  std::vector<std::vector<int>> rows(X.rows());
  for (const auto& p : nt::brute_force_pairs(X, box, r)) {
    rows[p.i].push_back(p.j);
    rows[p.j].push_back(p.i);
  }
  for (auto& row : rows) std::sort(row.begin(), row.end());
  return rows;
}

void check_rows(const NeighbourList& list, const VertexMatrix& X) {
  const auto expected = brute_force_rows(X, list.box(), list.radius());
  REQUIRE(list.particle_count() == X.rows());
  REQUIRE(list.offsets().size() == static_cast<std::size_t>(X.rows()) + 1);
  std::size_t total = 0;
  long wrong_rows = 0;
  for (int i = 0; i < X.rows(); ++i) {
    const auto row = list.neighbours_of(i);
    wrong_rows += std::vector<int>(row.begin(), row.end()) != expected[i];
    total += expected[i].size();
  }
  CHECK(wrong_rows == 0);
  CHECK(list.neighbours().size() == total);
  CHECK(list.pair_count() == total / 2);
}

// Restores the OpenMP thread count when a test ends, pass or fail.
struct ThreadCount {
  int saved = omp_get_max_threads();
  ~ThreadCount() { omp_set_num_threads(saved); }
};
}  // namespace

TEST_CASE("NeighbourList rows equal brute force within cutoff + skin", "[neighbours][neighbour_list]") {
  std::uint64_t seed = 11;
  for (int flags : {0, 1, 6, 7})
    for (double skin : {0.0, 0.3}) {
      Box box;
      box.lower << 0.5, -1, 2;
      box.lengths << 6, 4, 5;
      box.periodic = {(flags & 1) != 0, (flags & 2) != 0, (flags & 4) != 0};
      INFO("periodic " << flags << " skin " << skin);
      NeighbourList list(box, 1.0, skin);
      const VertexMatrix X = nt::random_points(700, box, seed++, 0.2);
      list.build(X);
      check_rows(list, X);
      CHECK(list.builds() == 1);
    }
}

TEST_CASE("NeighbourList in 2D, periodic, with 2 cells along an axis", "[neighbours][neighbour_list]") {
  const Box box = make_planar_box(Eigen::Vector2d(0, 0), Eigen::Vector2d(12, 2.4), true, true);
  NeighbourList list(box, 1.0, 0.2);  // 2.4 / 1.2: exactly two cells along y, with the margin one
  CHECK(list.grid().cells_per_axis() == Eigen::Vector3i(9, 1, 1));
  const VertexMatrix X = nt::random_points(500, box, 21, 0.3);
  list.build(X);
  check_rows(list, X);
  NeighbourList two(make_planar_box(Eigen::Vector2d(0, 0), Eigen::Vector2d(12, 2.5), true, true), 1.0, 0.2);
  CHECK(two.grid().cells_per_axis() == Eigen::Vector3i(9, 2, 1));  // 12 / 1.2 = 10 exactly: 9
  two.build(X);
  check_rows(two, X);
}

TEST_CASE("NeighbourList is the same for 1 and 2 OpenMP threads", "[neighbours][neighbour_list]") {
  ThreadCount restore;
  Box box;
  box.lengths << 12, 12, 12;
  box.periodic = {true, true, true};
  const VertexMatrix X = nt::random_points(5000, box, 31);
  omp_set_num_threads(1);
  NeighbourList one(box, 1.0, 0.1);
  one.build(X);
  omp_set_num_threads(2);
  NeighbourList two(box, 1.0, 0.1);
  two.build(X);
  CHECK(one.offsets() == two.offsets());
  CHECK(one.neighbours() == two.neighbours());
  CHECK(one.pair_count() > 5000);
  // rebuilding on the same object with another thread count changes nothing either
  omp_set_num_threads(1);
  two.build(X);
  CHECK(one.neighbours() == two.neighbours());
}

TEST_CASE("NeighbourList::needs_rebuild triggers past skin/2", "[neighbours][neighbour_list]") {
  Box box;
  box.lengths << 5, 5, 5;
  box.periodic = {true, true, false};
  const double skin = 0.4;
  NeighbourList list(box, 1.0, skin);
  VertexMatrix X = nt::random_points(200, box, 41);
  CHECK(list.needs_rebuild(X));  // never built
  list.build(X);
  CHECK_FALSE(list.needs_rebuild(X));

  VertexMatrix Y = X;
  Y(17, 0) += 0.199;
  Y(18, 1) -= 0.199;
  CHECK_FALSE(list.needs_rebuild(Y));
  Y(19, 2) += 0.201;  // one particle past skin/2 is enough
  CHECK(list.needs_rebuild(Y));

  VertexMatrix diagonal = X;  // 0.15 along each axis: 0.26 in all
  diagonal.row(5) += Eigen::RowVector3d(0.15, 0.15, 0.15);
  CHECK(list.needs_rebuild(diagonal));

  VertexMatrix wrapped = X;  // a whole period along a periodic axis is no move
  wrapped(3, 0) += 5;
  wrapped(4, 1) -= 10;
  CHECK_FALSE(list.needs_rebuild(wrapped));
  wrapped(4, 2) += 5;  // z is not periodic
  CHECK(list.needs_rebuild(wrapped));

  CHECK(list.needs_rebuild(X.topRows(199)));
  CHECK_FALSE(list.update(X));
  CHECK(list.update(Y));
  CHECK(list.builds() == 2);
  CHECK_FALSE(list.needs_rebuild(Y));
}

TEST_CASE("NeighbourList holds every pair within the cutoff while no one moved past skin/2", "[neighbours][neighbour_list]") {
  Box box;
  box.lengths << 7, 6, 5;
  box.periodic = {true, false, true};
  const double cutoff = 1.0, skin = 0.3;
  NeighbourList list(box, cutoff, skin);
  const VertexMatrix X = nt::random_points(900, box, 51);
  list.build(X);
  cmp::Random random(52);
  for (int trial = 0; trial < 3; ++trial) {
    VertexMatrix Y = X;
    for (int i = 0; i < Y.rows(); ++i) {  // each moves up to skin/2, in a random direction
      Eigen::RowVector3d step(random.normal(), random.normal(), random.normal());
      Y.row(i) += step.normalized() * (skin / 2) * random.uniform();
    }
    REQUIRE_FALSE(list.needs_rebuild(Y));
    long missing = 0, found = 0;
    for (const auto& p : nt::brute_force_pairs(Y, box, cutoff)) {
      const auto row = list.neighbours_of(p.i);
      std::binary_search(row.begin(), row.end(), p.j) ? ++found : ++missing;
    }
    CHECK(missing == 0);
    CHECK(found > 1000);
  }
}

TEST_CASE("NeighbourList rejects bad parameters", "[neighbours][neighbour_list]") {
  Box box;
  box.lengths << 4, 4, 4;
  box.periodic = {true, true, true};
  CHECK_THROWS_AS(NeighbourList(box, 1.9, 0.2), cmp::UsageError);  // 2.1 > L/2
  CHECK_NOTHROW(NeighbourList(box, 1.8, 0.2));
  CHECK_THROWS_AS(NeighbourList(box, 1.0, -0.1), cmp::UsageError);
  CHECK_THROWS_AS(NeighbourList(box, 0.0, 0.1), cmp::UsageError);
  NeighbourList list(box, 1.0, 0.1);
  list.build(VertexMatrix(0, 3));
  CHECK(list.particle_count() == 0);
  CHECK(list.neighbours().empty());
}

TEST_CASE("A parallel force loop over the list, as documented, equals brute force", "[neighbours][neighbour_list]") {
  // Harmonic soft spheres of diameter 1: f_i = sum_j (1 - r) d / r over r < 1.
  Box box;
  box.lengths << 6, 6, 6;
  box.periodic = {true, true, true};
  const double cutoff = 1.0;
  const VertexMatrix X = nt::random_points(1000, box, 71, 0.5);
  NeighbourList list(box, cutoff, 0.2);
  list.build(X);
  const int n = static_cast<int>(X.rows());
  VertexMatrix force = VertexMatrix::Zero(n, 3);
#pragma omp parallel for
  for (int i = 0; i < n; ++i)
    for (int j : list.neighbours_of(i)) {
      const Eigen::Vector3d d = list.minimum_image(X.row(i) - X.row(j));  // x_i - x_j
      const double r = d.norm();
      if (r < cutoff) force.row(i) += (1 - r) / r * d.transpose();
    }
  VertexMatrix expected = VertexMatrix::Zero(n, 3);
  for (const auto& p : nt::brute_force_pairs(X, box, cutoff)) {
    const double r = std::sqrt(p.r2);
    expected.row(p.i) += (1 - r) / r * p.d.transpose();
    expected.row(p.j) -= (1 - r) / r * p.d.transpose();
  }
  CHECK((force - expected).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(force.colwise().sum().norm() < 1e-10);  // Newton's third law
  CHECK(force.cwiseAbs().maxCoeff() > 0.5);
}
