#include "mesh/enclosed_volume.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

namespace {
constexpr VolumeMethod kMethods[] = {VolumeMethod::CentroidTetrahedra, VolumeMethod::DivergenceTheorem};
const char* name(VolumeMethod m) { return m == VolumeMethod::CentroidTetrahedra ? "tetrahedra" : "divergence"; }
}  // namespace

TEST_CASE("enclosed_volume of the cube, tetrahedron and octahedron", "[mesh][enclosed_volume]") {
  for (VolumeMethod method : kMethods) {
    INFO(name(method));
    const auto c = fx::unit_cube();
    CHECK(enclosed_volume(c.V, c.F, method) == Approx(1.0).epsilon(1e-15));
    const auto t = fx::regular_tetrahedron(2.5);
    CHECK(enclosed_volume(t.V, t.F, method) == Approx(std::pow(2.5, 3) / (6 * std::sqrt(2.0))).epsilon(1e-14));
    const auto o = fx::octahedron();
    CHECK(enclosed_volume(o.V, o.F, method) == Approx(4.0 / 3).epsilon(1e-15));
  }
  const auto c = fx::unit_cube();
  CHECK(enclosed_volume(c.V, c.F) == enclosed_volume(c.V, c.F, VolumeMethod::DivergenceTheorem));  // the default
}

TEST_CASE("enclosed_volume of UV spheres: the exact polyhedral volume, tending to 4 pi r^3 / 3", "[mesh][enclosed_volume]") {
  double previous_error = 1;
  for (int n : {8, 16, 32, 64}) {
    const auto s = fx::uv_sphere(n, n / 2, 1.5);
    const double exact = fx::uv_sphere_exact(n, n / 2, 1.5).volume;
    for (VolumeMethod method : kMethods) {
      INFO(name(method) << " n = " << n);
      CHECK(enclosed_volume(s.V, s.F, method) == Approx(exact).epsilon(1e-13));
    }
    const double error = 1 - exact / (4 * M_PI * std::pow(1.5, 3) / 3);
    CHECK(error > 0);                     // inscribed
    CHECK(error < previous_error / 3.5);  // second order: x4 per doubling
    previous_error = error;
  }
}

TEST_CASE("enclosed_volume of a torus: exact for both methods though not star-shaped", "[mesh][enclosed_volume]") {
  // No point sees the whole surface of a torus, yet the signed tetrahedra cancel exactly.
  const double R = 2.0, r = 0.7;
  double previous_error = 1;
  for (int n : {12, 24, 48, 96}) {
    const auto t = fx::torus(n, n / 2, R, r);
    const double exact = fx::torus_exact(n, n / 2, R, r).volume;
    for (VolumeMethod method : kMethods) {
      INFO(name(method) << " n = " << n);
      CHECK(enclosed_volume(t.V, t.F, method) == Approx(exact).epsilon(1e-13));
    }
    const double error = 1 - exact / (2 * M_PI * M_PI * R * r * r);
    CHECK(error > 0);
    CHECK(error < previous_error / 3.5);
    previous_error = error;
  }
  CHECK(previous_error < 4e-3);  // ~ ((2 pi/96)^2 + (2 pi/48)^2) / 6 = 3.6e-3
}

TEST_CASE("enclosed_volume: flipping every face negates it", "[mesh][enclosed_volume]") {
  for (const auto& m : {fx::unit_cube(), fx::uv_sphere(12, 6, 1), fx::torus(16, 8, 2, 0.5)})
    for (VolumeMethod method : kMethods) {
      const double v = enclosed_volume(m.V, m.F, method);
      CHECK(v > 0);
      CHECK(enclosed_volume(m.V, fx::flipped_all(m.F), method) == Approx(-v).epsilon(1e-14));
    }
}

TEST_CASE("enclosed_volume with one flipped face: both wrong, each in its own way", "[mesh][enclosed_volume]") {
  // Tetrahedra: each of the 12 faces and the centre (1/2, 1/2, 1/2) span 1/12; a flip turns
  // one +1/12 into -1/12. Divergence (F = (x,0,0)): a face of x = 1 contributes
  // (x_c - 1/2) n_x A = 1/4, a face of y = 1 nothing at all.
  auto c = fx::unit_cube();
  fx::flip_face(c.F, 10);  // x = 1
  CHECK(enclosed_volume(c.V, c.F, VolumeMethod::CentroidTetrahedra) == Approx(5.0 / 6).epsilon(1e-15));
  CHECK(enclosed_volume(c.V, c.F, VolumeMethod::DivergenceTheorem) == Approx(0.5).epsilon(1e-15));
  auto d = fx::unit_cube();
  fx::flip_face(d.F, 6);  // y = 1
  CHECK(enclosed_volume(d.V, d.F, VolumeMethod::CentroidTetrahedra) == Approx(5.0 / 6).epsilon(1e-15));
  CHECK(enclosed_volume(d.V, d.F, VolumeMethod::DivergenceTheorem) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("enclosed_volume is translation invariant, also in floating point", "[mesh][enclosed_volume]") {
  const auto s = fx::uv_sphere(40, 20, 1.0);
  const double exact = fx::uv_sphere_exact(40, 20, 1.0).volume;
  const Eigen::RowVector3d shift(1e6, -2e6, 3e6);
  const auto far = fx::translated(s, shift);
  for (VolumeMethod method : kMethods) {
    INFO(name(method));
    // The vertices themselves carry ~1e-10 of rounding at 1e6: that bounds what is possible.
    CHECK(enclosed_volume(far.V, far.F, method) == Approx(exact).epsilon(1e-8));
  }
  // The textbook (1/6) sum a.(b x c) on raw coordinates loses everything there.
  double naive = 0;
  for (Eigen::Index f = 0; f < far.F.rows(); ++f)
    naive += far.V.row(far.F(f, 0)).dot(far.V.row(far.F(f, 1)).cross(far.V.row(far.F(f, 2)))) / 6;
  CHECK(std::abs(naive - exact) > 1e-6);
}

TEST_CASE("enclosed_volume ignores unused vertices and is zero for no faces", "[mesh][enclosed_volume]") {
  auto c = fx::unit_cube();
  c.V.conservativeResize(9, 3);
  c.V.row(8) << 1e9, 1e9, 1e9;
  for (VolumeMethod method : kMethods) CHECK(enclosed_volume(c.V, c.F, method) == Approx(1.0).epsilon(1e-15));
  CHECK(enclosed_volume(c.V, FaceMatrix(0, 3)) == 0.0);
}
