#include "neighbours/sphere_grid.hpp"

#include "core/errors.hpp"
#include "neighbours_test_support.hpp"

#include <catch2/catch.hpp>

using namespace cmp::neighbours;
using cmp::mesh::VertexMatrix;
namespace nt = cmp::neighbours::testing;

TEST_CASE("make_sphere_grid covers the sphere's bounding cube, not periodic", "[neighbours][sphere_grid]") {
  const CellGrid grid = make_sphere_grid(3.0, 0.5, Eigen::Vector3d(1, 2, 3));
  CHECK(grid.box().lower == Eigen::Vector3d(-2, -1, 0));
  CHECK(grid.box().lengths == Eigen::Vector3d(6, 6, 6));
  CHECK(grid.box().periodic == std::array<bool, 3>{false, false, false});
  CHECK(grid.cells_per_axis() == Eigen::Vector3i(11, 11, 11));  // 6 / 0.5 = 12 exactly: 11
  CHECK_THROWS_AS(make_sphere_grid(0.0, 0.5), cmp::UsageError);
  CHECK_THROWS_AS(make_sphere_grid(1.0, 0.0), cmp::UsageError);
}

TEST_CASE("make_sphere_grid finds the brute-force pairs of random points on a sphere", "[neighbours][sphere_grid]") {
  for (double cutoff : {0.15, 0.4, 1.3}) {
    INFO("cutoff " << cutoff);
    const double radius = 2.0;
    VertexMatrix X = nt::random_points_on_sphere(1500, radius, 61);
    // the poles and the ends of the axes lie exactly on the faces of the cube
    X.topRows(6) << radius, 0, 0, -radius, 0, 0, 0, radius, 0, 0, -radius, 0, 0, 0, radius, 0, 0, -radius;
    X.row(6) *= 1.05;  // off the sphere, and out of the cube for some
    X.row(7) *= 0.95;
    X.row(8) << 3, 3, 3;
    CellGrid grid = make_sphere_grid(radius, cutoff);
    grid.build(X);
    const auto expected = nt::brute_force_pairs(X, grid.box(), cutoff);
    std::vector<nt::Pair> found;
    grid.for_each_pair(X, [&](int i, int j, const Eigen::Vector3d& d, double r2) { found.push_back(nt::canonical(i, j, d, r2)); });
    std::sort(found.begin(), found.end());
    REQUIRE(found.size() == expected.size());
    long wrong = 0;
    for (std::size_t k = 0; k < found.size(); ++k)
      wrong += found[k].i != expected[k].i || found[k].j != expected[k].j || found[k].d != expected[k].d;
    CHECK(wrong == 0);
    // about N^2/2 times the area fraction of a cap of chord radius c: c^2 / (4 R^2)
    const double mean = 1500.0 * 1499 / 2 * cutoff * cutoff / (4 * radius * radius);
    CHECK(static_cast<double>(found.size()) == Approx(mean).epsilon(0.1));
  }
}
