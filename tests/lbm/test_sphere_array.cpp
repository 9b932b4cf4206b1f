// The simple cubic array of spheres against the classical Stokes drag results, and what
// interpolated bounce-back does to the staircase error of the voxel image.
#include "lbm/flow_solver.hpp"
#include "lbm/sphere_lattice.hpp"
#include "lbm/steady_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace cmp::lbm;

namespace {

// c = 0.125, K = 4.292: Zick & Homsy's table (lbm/sphere_lattice.hpp).
constexpr double kSolidFraction = 0.125, kDrag = 4.292;

double reference_kappa(int n) { return sphere_array_kappa(n, kSolidFraction, kDrag); }

// kappa of one sphere of the array in an n^3 box, its centre shifted by `shift` nodes.
double kappa(int n, double shift, bool interpolated, double tau = 1.0, double tol = 1e-6) {
  const double a = n * std::cbrt(3 * kSolidFraction / (4 * std::numbers::pi));
  const double c = 0.5 * (n - 1);
  PoreLattice p = periodic_spheres(n, n, n, {{c + shift, c - 0.5 * shift, c + 0.3 * shift, a}});
  if (!interpolated) p.wall_fraction = nullptr;
  FlowSettings s;
  s.driving = Driving::kBodyForce;
  s.collision_parameters.tau = tau;
  const SteadyStateResult r = solve_steady(p, s, {tol, 50, 4, 100000});
  REQUIRE(r.converged);
  return r.final.kappa_lu;
}

}  // namespace

TEST_CASE("sphere array: Hasimoto's series and Zick & Homsy's table agree where the series holds") {
  bool found = false;
  for (const DragReference& r : zick_homsy_simple_cubic()) {
    if (r.solid_fraction == kSolidFraction) found = r.K == kDrag;
    if (r.solid_fraction <= 0.216) CHECK(std::abs(hasimoto_drag(r.solid_fraction) / r.K - 1) < 0.01);
  }
  CHECK(found);
  CHECK(std::abs(hasimoto_drag(1e-6) - 1) < 0.02);  // a lone sphere: Stokes drag
}

TEST_CASE("sphere array: kappa within 3 % of Zick & Homsy at radius 7.4 (n = 24), closer than at n = 16") {
  const double e16 = kappa(16, 0, true) / reference_kappa(16) - 1;
  const double e24 = kappa(24, 0, true) / reference_kappa(24) - 1;
  const double h24 = kappa(24, 0, false) / reference_kappa(24) - 1;
  INFO("interpolated error n=16 " << e16 << " n=24 " << e24 << ", half-way n=24 " << h24);
  CHECK(std::abs(e24) < 0.03);
  CHECK(std::abs(h24) < 0.03);
  CHECK(std::abs(e24) < 0.5 * std::abs(e16));
}

TEST_CASE("sphere array: interpolated bounce-back removes most of the staircase scatter (n = 16, shifted spheres)") {
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (double shift : {0.0, 0.2, 0.35, 0.5})
    for (int interp = 0; interp < 2; ++interp) {
      const double k = kappa(16, shift, interp == 1) / reference_kappa(16);
      lo[interp] = std::min(lo[interp], k);
      hi[interp] = std::max(hi[interp], k);
    }
  INFO("half-way " << lo[0] << ".." << hi[0] << ", interpolated " << lo[1] << ".." << hi[1]);
  CHECK(hi[0] - lo[0] > 0.05);
  CHECK(hi[1] - lo[1] < 0.3 * (hi[0] - lo[0]));
}

TEST_CASE("sphere array: the bench's random sphere box is below its porosity target, and the same for the same seed") {
  const auto a = random_sphere_box(24, 0.35, 2026);
  const auto b = random_sphere_box(24, 0.35, 2026);
  const auto c = random_sphere_box(24, 0.35, 7);
  CHECK(a.porosity() < 0.35);
  CHECK(a.porosity() > 0.25);  // stops at the first batch of 16 spheres below the target
  CHECK(a.fluid == b.fluid);
  CHECK(a.fluid != c.fluid);
  CHECK(!a.wall_fraction);
}

TEST_CASE("sphere array: lbflow's default tau on images (0.55) gives the kappa of tau = 1, interpolated walls move") {
  // Half-way walls: the steady flow of mrt depends on tau only through the magic parameter
  // (measured 1.1e-4 apart, the rest of the tol 1e-9 runs). Interpolated (Bouzidi) walls do not
  // share that invariance (2.4 % apart): lbflow keeps tau = 1 for sphere packings.
  const double h1 = kappa(16, 0, false, 1.0, 1e-9), h055 = kappa(16, 0, false, 0.55, 1e-9);
  const double i1 = kappa(16, 0, true, 1.0, 1e-9), i055 = kappa(16, 0, true, 0.55, 1e-9);
  INFO("half-way: tau 1 " << h1 << ", 0.55 " << h055 << "; interpolated: " << i1 << ", " << i055
                          << "; Zick & Homsy " << reference_kappa(16));
  CHECK(std::abs(h055 / h1 - 1) < 2e-4);
  CHECK(std::abs(i055 / i1 - 1) > 0.01);
}
