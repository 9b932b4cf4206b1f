#include "mesh/face_areas.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

TEST_CASE("face_areas of the unit cube: twelve halves of unit squares", "[mesh][face_areas]") {
  const auto m = fx::unit_cube();
  const Eigen::VectorXd a = face_areas(m.V, m.F);
  REQUIRE(a.size() == 12);
  for (Eigen::Index f = 0; f < a.size(); ++f) CHECK(a[f] == Approx(0.5).epsilon(1e-15));
  CHECK(total_area(m.V, m.F) == Approx(6.0).epsilon(1e-15));
}

TEST_CASE("face_areas of a regular tetrahedron and an octahedron", "[mesh][face_areas]") {
  const double edge = 1.7;
  const auto t = fx::regular_tetrahedron(edge);
  for (double a : face_areas(t.V, t.F)) CHECK(a == Approx(std::sqrt(3.0) / 4 * edge * edge).epsilon(1e-14));
  CHECK(total_area(t.V, t.F) == Approx(std::sqrt(3.0) * edge * edge).epsilon(1e-14));

  const auto o = fx::octahedron();
  for (double a : face_areas(o.V, o.F)) CHECK(a == Approx(std::sqrt(3.0) / 2).epsilon(1e-15));
  CHECK(total_area(o.V, o.F) == Approx(4 * std::sqrt(3.0)).epsilon(1e-15));
}

TEST_CASE("face_areas of a single triangle, a degenerate one, and an unused vertex", "[mesh][face_areas]") {
  auto m = fx::single_triangle();
  CHECK(total_area(m.V, m.F) == 6.0);
  m.V.row(2) << 6, 0, 0;  // collinear: zero area, not NaN
  CHECK(face_areas(m.V, m.F)[0] == 0.0);

  TriMesh with_unused = fx::single_triangle();
  with_unused.V.conservativeResize(4, 3);
  with_unused.V.row(3) << 100, 100, 100;
  CHECK(total_area(with_unused.V, with_unused.F) == 6.0);
}

TEST_CASE("total_area of a UV sphere and a torus equals the exact polyhedral area", "[mesh][face_areas]") {
  for (int n : {6, 12, 48}) {
    INFO("n = " << n);
    const auto s = fx::uv_sphere(n, n / 2, 2.0);
    CHECK(total_area(s.V, s.F) == Approx(fx::uv_sphere_exact(n, n / 2, 2.0).area).epsilon(1e-13));
    const auto t = fx::torus(n, n / 2, 3.0, 1.0);
    CHECK(total_area(t.V, t.F) == Approx(fx::torus_exact(n, n / 2, 3.0, 1.0).area).epsilon(1e-13));
  }
  // and approaches the smooth surfaces: 4 pi r^2, 4 pi^2 R r (error ~ 1/n^2)
  const auto s = fx::uv_sphere(200, 100, 2.0);
  CHECK(total_area(s.V, s.F) == Approx(16 * M_PI).epsilon(1e-3));
  CHECK(total_area(s.V, s.F) < 16 * M_PI);  // inscribed
  const auto t = fx::torus(200, 100, 3.0, 1.0);
  CHECK(total_area(t.V, t.F) == Approx(12 * M_PI * M_PI).epsilon(1e-3));
}

TEST_CASE("face_areas are translation invariant", "[mesh][face_areas]") {
  const auto s = fx::uv_sphere(24, 12, 1.0);
  const auto far = fx::translated(s, Eigen::RowVector3d(1e6, -2e6, 3e6));
  const Eigen::VectorXd a = face_areas(s.V, s.F), b = face_areas(far.V, far.F);
  CHECK((a - b).cwiseAbs().maxCoeff() < 1e-8 * a.minCoeff());
}
