#include "elasticity/membrane_contact.hpp"

#include "core/errors.hpp"
#include "elasticity/pressurised_sphere.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace cmp::elasticity;

namespace {
// Fig. B.9: P/E = 0.0025, t/R0 = 0.04, nu = 0.5 (units E = 1, R0 = 1).
const Sheet fig_b9{1.0, 0.5, 0.04};
const double P_i = 0.0025;

double slope(const MembraneContact& a, const MembraneContact& b) {
  return std::log(b.force / a.force) / std::log(b.compression / a.compression);
}
}  // namespace

TEST_CASE("uncompressed, the membrane is the free SVK sphere", "[elasticity][membrane]") {
  const InflatedMembrane m(fig_b9, 1.0, P_i);
  CHECK(m.inflated_stretch() == Approx(sphere_stretch(fig_b9, 1.0, P_i)).epsilon(1e-15));
  const auto s = m.free_state();
  CHECK(s.force == 0);
  CHECK(s.equator_force == Approx(0).margin(1e-15));
  // Shooting from the pole without contact, at the sphere's stretch and pressure, draws the
  // inflated sphere: the meridian is a circle of radius R_i with uniform stretch.
  const auto mer = m.meridian(s, 20);
  REQUIRE(mer.size() == 21);
  for (const auto& q : mer) {
    INFO("psi = " << q.psi);
    CHECK(q.rho == Approx(m.inflated_radius() * std::sin(q.psi)).margin(1e-9));
    CHECK(q.eta == Approx(m.inflated_radius() * std::cos(q.psi)).margin(1e-9));
    CHECK(q.lambda1 == Approx(m.inflated_stretch()).epsilon(1e-9));
    CHECK(q.lambda2 == Approx(m.inflated_stretch()).epsilon(1e-9));
  }
}

TEST_CASE("constant-volume compression of Fig. B.9: balance, volume and virtual work", "[elasticity][membrane]") {
  const InflatedMembrane m(fig_b9, 1.0, P_i);
  std::vector<double> X;
  for (double x : {0.001, 0.002, 0.05, 0.1, 0.1 + 1e-4, 0.2, 0.3, 0.4, 0.4 + 1e-4, 0.5})
    X.push_back(x);
  const auto r = m.sweep(X, Fill::ConstantVolume);
  REQUIRE(r.size() == X.size());
  for (const auto& s : r) {
    INFO("X = " << s.compression);
    CHECK(s.residual < 1e-9);
    CHECK(s.volume == Approx(m.inflated_volume()).epsilon(1e-9));
    CHECK(s.half_gap == Approx((1 - s.compression) * m.inflated_radius()).epsilon(1e-14));
    // B.106 and the vertical balance at the equator are independent.
    CHECK(s.force == Approx(M_PI * s.pressure * s.contact_radius * s.contact_radius).epsilon(1e-14));
    CHECK(s.equator_force == Approx(s.force).epsilon(1e-6));
    // ... and the same first integral holds on every horizontal cut of the free part.
    for (const auto& q : m.meridian(s, 50))
      if (q.psi > s.contact_angle) CHECK(q.vertical_force == Approx(s.force).epsilon(1e-6));
  }
  // Virtual work at constant volume: dU = -2 F d eta_bar (checks the ODEs against the energy B.92).
  for (int i : {3, 7}) {
    const double dU = r[i + 1].energy - r[i].energy, deta = r[i + 1].half_gap - r[i].half_gap;
    INFO("X = " << r[i].compression);
    CHECK(-dU / (2 * deta) == Approx(0.5 * (r[i].force + r[i + 1].force)).epsilon(1e-4));
  }
  // Pressure rises, contact grows, force increases monotonically.
  for (std::size_t i = 1; i < r.size(); ++i) {
    CHECK(r[i].force > r[i - 1].force);
    CHECK(r[i].pressure > r[i - 1].pressure);
    CHECK(r[i].contact_radius > r[i - 1].contact_radius);
  }
  // Reference numbers of this solver (F^ = F/(E t R0), P* = P/P_i), to catch regressions.
  CHECK(r[3].force / m.force_scale() == Approx(1.1984e-3 / 0.04).epsilon(1e-3));
  CHECK(r[3].pressure / P_i == Approx(1.18365).epsilon(1e-4));
  CHECK(r[5].pressure / P_i == Approx(1.78694).epsilon(1e-4));
  // Small compression is not Hertzian: F ~ X / ln(1/X)-like, local exponent ~1.2 at X = 1e-3
  // (tending to 1), passing 3/2 near X = 0.1, and stiffening beyond (2 and more).
  CHECK(slope(r[0], r[1]) == Approx(1.2).margin(0.05));
  CHECK(slope(r[2], r[3]) == Approx(1.5).margin(0.1));
  CHECK(slope(r[6], r[7]) > 2.0);
}

TEST_CASE("at vanishing compression the force is linear up to a logarithm, not Hertzian", "[elasticity][membrane]") {
  // A tense membrane indented over a small contact: F ~ 4 pi T delta / ln(1/X) (delta = X R_i,
  // T the inflated tension), so the local exponent falls slowly towards 1 (1.10 at X = 1e-5).
  const InflatedMembrane m(fig_b9, 1.0, P_i);
  const auto r = m.sweep({1e-5, 1.1e-5}, Fill::ConstantVolume);
  CHECK(slope(r[0], r[1]) == Approx(1.10).margin(0.02));
  const double T = sphere_tension(fig_b9, m.inflated_stretch());
  const double delta = r[0].compression * m.inflated_radius();
  CHECK(r[0].force * std::log(1 / r[0].compression) / (4 * M_PI * T * delta) == Approx(1.0).margin(0.1));
}

TEST_CASE("constant-pressure compression keeps P and loses volume until the meridian goes slack",
          "[elasticity][membrane]") {
  const InflatedMembrane m(fig_b9, 1.0, P_i);
  const auto r = m.sweep({0.01, 0.05, 0.1, 0.1 + 1e-4, 0.15}, Fill::ConstantPressure);
  for (const auto& s : r) {
    CHECK(s.pressure == Approx(P_i).epsilon(1e-14));
    CHECK(s.volume < m.inflated_volume());
    CHECK(s.equator_force == Approx(s.force).epsilon(1e-6));
  }
  // Virtual work with the fluid's work: dU = -2 F d eta_bar + P dV.
  const double dU = r[3].energy - r[2].energy, deta = r[3].half_gap - r[2].half_gap, dV = r[3].volume - r[2].volume;
  CHECK(-(dU - P_i * dV) / (2 * deta) == Approx(0.5 * (r[2].force + r[3].force)).epsilon(1e-4));
  // Beyond X ~ 0.22 the meridional tension at the contact edge would be compressive: no taut
  // membrane solution.
  CHECK_THROWS_AS(m.sweep({0.3}, Fill::ConstantPressure), cmp::ComputationError);
  CHECK_THROWS_AS(InflatedMembrane(fig_b9, 1.0, 0.0), cmp::UsageError);
  CHECK_THROWS_AS(m.sweep({0.2, 0.1}, Fill::ConstantVolume), cmp::UsageError);
}
