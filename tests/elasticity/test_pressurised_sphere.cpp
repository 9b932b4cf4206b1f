#include "elasticity/pressurised_sphere.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::elasticity;

namespace {
// Fig. B.4A: R0 = 2.5, t = 0.1, E = 25e6, nu = 1/3.
const Sheet fig_b4{25e6, 1.0 / 3.0, 0.1};
const double kSphereR0 = 2.5;
}  // namespace

TEST_CASE("the SVK sphere's equilibrium is stationary energy, not the printed B.81", "[elasticity][sphere]") {
  // d/dlambda [4 pi R0^2 W(lambda) - dP (4/3) pi R0^3 lambda^3] = 0 with W of Eq. B.80,
  // differentiated numerically here, independently of the closed form.
  const Sheet s{3.0, 0.3, 0.2};
  const double r0 = 1.7;
  auto W = [&](double l) { return s.youngs_modulus * s.thickness * std::pow(l * l - 1, 2) / (4 * (1 - s.poisson_ratio)); };
  for (double lambda : {1.01, 1.1, 1.5, 2.0}) {
    const double dP = sphere_pressure(s, r0, lambda);
    auto G = [&](double l) { return 4 * M_PI * r0 * r0 * W(l) - dP * 4.0 / 3.0 * M_PI * std::pow(r0, 3) * l * l * l; };
    const double h = 1e-6;
    CHECK((G(lambda + h) - G(lambda - h)) / (2 * h) == Approx(0).margin(1e-6 * dP * r0 * r0 * r0));
    // Laplace's law with the Cauchy tension.
    CHECK(dP == Approx(2 * sphere_tension(s, lambda) / (lambda * r0)).epsilon(1e-14));
    // The printed B.81 is lambda^2 times the equilibrium pressure.
    CHECK(sphere_pressure_printed(s, r0, lambda) == Approx(lambda * lambda * dP).epsilon(1e-14));
    CHECK(sphere_stretch(s, r0, dP) == Approx(lambda).epsilon(1e-14));
  }
  CHECK(sphere_stretch(s, r0, 0.0) == 1.0);
  CHECK(sphere_stretch(s, r0, -0.1) < 1.0);
  CHECK(sphere_pressure(s, r0, sphere_stretch(s, r0, -0.1)) == Approx(-0.1).epsilon(1e-12));
}

TEST_CASE("SVK sphere strain against the reference table of Fig. B.4A", "[elasticity][sphere]") {
  // eps_r at dP/E = 1e-4 .. 1e-2: linear / printed B.82 / corrected.
  struct Row { double p, linear, printed, corrected; };
  const Row rows[] = {{1e-4, 0.00083, 0.00083, 0.00083}, {1e-3, 0.00833, 0.00823, 0.00837},
                      {2e-3, 0.01667, 0.01627, 0.01681}, {5e-3, 0.04167, 0.03932, 0.04253},
                      {1e-2, 0.08333, 0.07474, 0.08680}};
  for (const auto& r : rows) {
    const double dP = r.p * fig_b4.youngs_modulus;
    INFO("dP/E = " << r.p);
    CHECK(sphere_strain_linear(fig_b4, kSphereR0, dP) == Approx(r.linear).margin(5e-6));
    CHECK(sphere_strain_printed(fig_b4, kSphereR0, dP) == Approx(r.printed).margin(5e-6));
    CHECK(sphere_stretch(fig_b4, kSphereR0, dP) - 1 == Approx(r.corrected).margin(5e-6));
  }
  // The printed B.82 solves its own cubic.
  const double e = sphere_strain_printed(fig_b4, kSphereR0, 0.01 * fig_b4.youngs_modulus);
  CHECK(e + 1.5 * e * e + 0.5 * e * e * e == Approx(0.01 * 25 * (2.0 / 3.0) / 2).epsilon(1e-12));
  // All three agree at small strain (relative difference ~ eps_r).
  const double small = 1e-7 * fig_b4.youngs_modulus;
  CHECK(sphere_stretch(fig_b4, kSphereR0, small) - 1 == Approx(sphere_strain_linear(fig_b4, kSphereR0, small)).epsilon(1e-5));
}
