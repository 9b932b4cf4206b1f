// The one Hertz law (forcefield/hertz.hpp) that every contact style uses.
#include "forcefield/hertz.hpp"

#include <catch2/catch.hpp>

using namespace cmp;

TEST_CASE("Hertz law: E* = 2/3 for E = 1, nu = 0.5, and the force is minus the energy's derivative") {
  const HertzMaterial m;
  CHECK(m.effective_modulus() == Approx(2.0 / 3.0));
  CHECK(effective_radius(0.5, 0.5) == Approx(0.25));
  const double c = hertz_prefactor(m, 0.5, 0.5);
  CHECK(c == Approx(4.0 / 3.0 * 2.0 / 3.0 * 0.5));
  const double h = 0.01, dh = 1e-7;
  CHECK(hertz_force(c, h) == Approx((hertz_energy(c, h + dh) - hertz_energy(c, h - dh)) / (2 * dh)).epsilon(1e-8));
  CHECK(hertz_force(c, -0.1) == 0);
  CHECK(hertz_energy(c, 0) == 0);
}
