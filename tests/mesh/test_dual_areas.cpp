#include "mesh/dual_areas.hpp"

#include "mesh/face_areas.hpp"
#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

TEST_CASE("vertex_dual_areas of regular solids: equal shares", "[mesh][dual_areas]") {
  const auto o = fx::octahedron();  // every vertex in 4 faces of area sqrt(3)/2
  for (double c : vertex_dual_areas(o.V, o.F)) CHECK(c == Approx(2 * std::sqrt(3.0) / 3).epsilon(1e-15));
  const auto t = fx::regular_tetrahedron(3.0);  // every vertex in 3 faces of area sqrt(3)/4 a^2
  for (double c : vertex_dual_areas(t.V, t.F)) CHECK(c == Approx(std::sqrt(3.0) / 4 * 9).epsilon(1e-14));
}

TEST_CASE("vertex_dual_areas of the cube: a third of the half squares at each corner", "[mesh][dual_areas]") {
  const auto m = fx::unit_cube();
  const Eigen::VectorXd c = vertex_dual_areas(m.V, m.F);
  // Corners 0 and 7 lie on all three square diagonals (6 triangles), the others on one (4).
  for (int i = 0; i < 8; ++i) CHECK(c[i] == Approx((i == 0 || i == 7 ? 6 : 4) * 0.5 / 3).epsilon(1e-15));
  CHECK(c.sum() == Approx(6.0).epsilon(1e-15));
}

TEST_CASE("vertex_dual_areas sum to the total area", "[mesh][dual_areas]") {
  for (const auto& m : {fx::uv_sphere(20, 10, 1.3), fx::torus(30, 12, 2.0, 0.5), fx::moebius_strip(20, 2.0, 0.4)}) {
    const Eigen::VectorXd c = vertex_dual_areas(m.V, m.F);
    CHECK(c.size() == m.V.rows());
    CHECK(c.sum() == Approx(total_area(m.V, m.F)).epsilon(1e-14));
    CHECK(c.minCoeff() > 0);
  }
  // the poles of a UV sphere: a third of their fan of n_lon triangles
  const auto s = fx::uv_sphere(20, 10, 1.3);
  const Eigen::VectorXd a = face_areas(s.V, s.F), c = vertex_dual_areas(s.V, s.F);
  CHECK(c[0] == Approx(a.head(20).sum() / 3).epsilon(1e-14));
}

TEST_CASE("vertex_dual_areas: a vertex in no face gets zero, a lone triangle thirds", "[mesh][dual_areas]") {
  auto m = fx::single_triangle();
  m.V.conservativeResize(4, 3);
  m.V.row(3) << 1, 1, 1;
  const Eigen::VectorXd c = vertex_dual_areas(m.V, m.F);
  REQUIRE(c.size() == 4);
  CHECK(c[0] == 2.0);
  CHECK(c[1] == 2.0);
  CHECK(c[2] == 2.0);
  CHECK(c[3] == 0.0);
}
