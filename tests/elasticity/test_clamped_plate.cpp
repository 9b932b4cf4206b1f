#include "elasticity/clamped_plate.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::elasticity;

namespace {
// Figs. B.5-B.6: R0 = 2.25, t = 0.1, E = 25e6, nu = 1/3.
const Sheet plate{25e6, 1.0 / 3.0, 0.1};
const double R0 = 2.25;

// Second derivative and the axisymmetric biharmonic operator by finite differences.
template <class W>
double biharmonic(W w, double r, double h) {
  auto lap = [&](double x) { return (w(x + h) - 2 * w(x) + w(x - h)) / (h * h) + (w(x + h) - w(x - h)) / (2 * h * x); };
  return (lap(r + h) - 2 * lap(r) + lap(r - h)) / (h * h) + (lap(r + h) - lap(r - h)) / (2 * h * r);
}
}  // namespace

TEST_CASE("clamped plate reference numbers of Figs. B.5 and B.6", "[elasticity][plate]") {
  CHECK(plate.bending_rigidity() == Approx(2343.75).epsilon(1e-12));
  CHECK(point_load_max_deflection(plate, R0, 5e3) == Approx(0.21486).margin(5e-6));
  CHECK(point_load_max_deflection(plate, R0, 5e3) / plate.thickness > 2.0);  // outside the linear regime
  const double q = 1e3 / (M_PI * R0 * R0);
  CHECK(q == Approx(62.876).margin(1e-3));
  CHECK(uniform_load_max_deflection(plate, R0, q) == Approx(0.010743).margin(1e-6));
  CHECK(uniform_load_max_deflection(plate, R0, 1e3) == Approx(0.1709).margin(1e-4));
  CHECK(point_load_max_deflection(plate, R0, point_load_linear_limit(plate, R0)) == Approx(0.05).epsilon(1e-12));
  CHECK(uniform_load_max_deflection(plate, R0, uniform_load_linear_limit(plate, R0)) == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("clamped plate profiles satisfy the plate equation and the clamped edge", "[elasticity][plate]") {
  const double P0 = 1.0, q = 1.0, D = plate.bending_rigidity();
  auto wp = [&](double r) { return point_load_deflection(plate, R0, P0, r); };
  auto wq = [&](double r) { return uniform_load_deflection(plate, R0, q, r); };
  // Edge: w = 0, dw/dr = 0.
  const double h = 1e-5;
  CHECK(wp(R0) == Approx(0).margin(1e-15));
  CHECK(wq(R0) == Approx(0).margin(1e-15));
  CHECK((wp(R0) - wp(R0 - h)) / h == Approx(0).margin(1e-8));
  CHECK((wq(R0) - wq(R0 - h)) / h == Approx(0).margin(1e-8));
  CHECK(wp(0) == Approx(point_load_max_deflection(plate, R0, P0)).epsilon(1e-14));
  CHECK(wq(0) == Approx(uniform_load_max_deflection(plate, R0, q)).epsilon(1e-14));
  // D nabla^4 w = q away from the centre; = 0 for the point load (its 2 r^2 ln r term is the
  // biharmonic Green function; with the printed "2 r^2" read as a constant it would not be).
  for (double r : {0.5, 1.0, 1.7}) {
    CHECK(D * biharmonic(wq, r, 1e-2) == Approx(q).epsilon(1e-4));
    CHECK(D * biharmonic(wp, r, 1e-2) == Approx(0).margin(1e-4 * P0 / (R0 * R0)));
  }
  // The shear at radius r carries the whole load (w > 0 along the load): D d/dr(nabla^2 w) = P0/(2 pi r).
  const double r = 1.0, e = 1e-3;
  auto lap = [&](double x) { return (wp(x + e) - 2 * wp(x) + wp(x - e)) / (e * e) + (wp(x + e) - wp(x - e)) / (2 * e * x); };
  CHECK(D * (lap(r + e) - lap(r - e)) / (2 * e) == Approx(P0 / (2 * M_PI * r)).epsilon(1e-4));
  CHECK_THROWS_AS(point_load_deflection(plate, R0, P0, R0 * 1.01), std::domain_error);
}

TEST_CASE("large deflection of a clamped plate: the nu = 0 table of Fig. B.7", "[elasticity][plate]") {
  const double table[][2] = {{0.1, 0.01875},  {1, 0.18437},   {3, 0.50000},    {10, 1.13804},   {30, 1.94515},
                             {100, 3.14824},  {300, 4.68939}, {1000, 7.11880}, {3000, 10.33632}, {1e4, 15.49325}};
  for (const auto& row : table) {
    INFO("P* = " << row[0]);
    const double w = large_deflection_max_deflection(0.0, row[0]);
    CHECK(w == Approx(row[1]).margin(5e-6));
    CHECK(large_deflection_load_star(0.0, w) == Approx(row[0]).epsilon(1e-11));
  }
  CHECK(large_deflection_max_deflection(0.0, 0.0) == 0.0);
  CHECK_THROWS_AS(large_deflection_max_deflection(0.0, -1.0), std::domain_error);
  CHECK_THROWS_AS(large_deflection_max_deflection(0.7, 1.0), std::domain_error);
}

TEST_CASE("large deflection relation reduces to linear plate theory and agrees with B.88 at any nu",
          "[elasticity][plate]") {
  const Sheet s{25e6, 0.3, 0.1};
  const double R = 2.14;
  for (double w : {1e-4, 0.3, 2.0}) {
    // B.88 (dimensionally corrected) in SI units.
    const double wm = w * s.thickness;
    const double q88 = 64 * s.bending_rigidity() * wm / std::pow(R, 4) +
                       8.0 / 3.0 * s.youngs_modulus * s.thickness / (1 - s.poisson_ratio) * std::pow(wm, 3) / std::pow(R, 4);
    CHECK(plate_pressure_from_star(s, R, large_deflection_load_star(s.poisson_ratio, w)) == Approx(q88).epsilon(1e-12));
  }
  // Small load: w_max/t of the linear theory.
  const double q = 1e-3 * uniform_load_linear_limit(s, R);
  const double w = large_deflection_max_deflection(s.poisson_ratio, plate_load_star(s, R, q));
  CHECK(w * s.thickness == Approx(uniform_load_max_deflection(s, R, q)).epsilon(1e-6));
  // At the linear limit (w_max = t/2 linearly) the nonlinear deflection is 10-15 % smaller.
  const double wl = large_deflection_max_deflection(s.poisson_ratio, plate_load_star(s, R, uniform_load_linear_limit(s, R)));
  CHECK(wl / 0.5 == Approx(0.86).margin(0.03));
  CHECK(plate_load_star(s, R, plate_pressure_from_star(s, R, 7.0)) == Approx(7.0).epsilon(1e-14));
}
