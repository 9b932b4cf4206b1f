// Flows with known answers: plane Poiseuille, the square duct, straight and tortuous
// channels, mass, the pressure profile, and the drag of a simple cubic array of spheres.
#include "lbm/flow_solver.hpp"
#include "lbm/pore_lattice.hpp"
#include "lbm/sphere_lattice.hpp"
#include "lbm/steady_state.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace cmp::lbm;

namespace {

FlowSettings settings(const char* collision, double tau, Driving driving = Driving::kPressure, int axis = 0) {
  FlowSettings s;
  s.collision = collision;
  s.collision_parameters.tau = tau;
  s.driving = driving;
  s.axis = axis;
  s.density_drop = 1e-3;
  s.body_force = 1e-6;
  return s;
}

FlowObservables steady(const PoreLattice& p, const FlowSettings& s, double tol = 1e-9, long every = 50) {
  const SteadyStateResult r = solve_steady(p, s, {tol, every, 4, 100000});
  REQUIRE(r.converged);
  return r.final;
}

// Permeability of a plane channel of H fluid nodes between two wall layers, over the whole
// box (H + 2 nodes across): the superficial average carries the porosity H / (H + 2).
double plane_kappa(int H) { return H * H / 12.0 * H / (H + 2.0); }

// Square duct of side a: mean velocity = G a^2 / (mu) * (1/12 - (16/pi^5) sum_odd tanh(n pi/2)/n^5)
// (e.g. White, Viscous Fluid Flow, Eq. 3-48 for a = b), so kappa over the duct's own
// section is a^2 * that bracket.
double duct_kappa(int a) {
  double s = 0;
  for (int n = 1; n < 200; n += 2) s += std::tanh(n * std::numbers::pi / 2) / std::pow(n, 5);
  const double k = a * a * (1.0 / 12 - 16 / std::pow(std::numbers::pi, 5) * s);
  return k * a * a / ((a + 2.0) * (a + 2.0));  // superficial over the box with its wall layers
}

// Relative spread (max - min) / min of kappa over the relaxation times.
double tau_spread(const PoreLattice& p, const char* style, std::initializer_list<double> taus, Driving driving,
                  double tol) {
  double lo = 1e9, hi = -1e9;
  for (double tau : taus) {
    const FlowObservables o = steady(p, settings(style, tau, driving), tol);
    lo = std::min(lo, o.kappa_lu);
    hi = std::max(hi, o.kappa_lu);
  }
  return (hi - lo) / lo;
}

}  // namespace

TEST_CASE("Poiseuille: plane channel, pressure driven, kappa within 1 % of h^2/12 at h = 10 (MRT, TRT)") {
  const PoreLattice p = channel(16, 10, 0, 1);
  for (const char* style : {"mrt", "trt"}) {
    const FlowObservables o = steady(p, settings(style, 1.0));
    INFO(style << " kappa/exact " << o.kappa_lu / plane_kappa(10));
    CHECK(std::abs(o.kappa_lu / plane_kappa(10) - 1) < 0.01);
    CHECK(o.mach < 0.1);
    CHECK(o.reynolds < 0.1);
    CHECK(std::abs(o.tortuosity - 1) < 1e-6);
  }
}

TEST_CASE("Poiseuille: second-order convergence with resolution (h = 5, 10, 20)") {
  for (const char* style : {"mrt", "trt"}) {
    double err[3];
    int k = 0;
    for (int h : {5, 10, 20}) {
      const FlowObservables o = steady(channel(2, h, 0, 1), settings(style, 1.0, Driving::kBodyForce), 1e-10);
      err[k++] = std::abs(o.kappa_lu / plane_kappa(h) - 1);
    }
    INFO(style << " errors " << err[0] << " " << err[1] << " " << err[2]);
    CHECK(err[0] / err[1] > 3.5);
    CHECK(err[0] / err[1] < 4.5);
    CHECK(err[1] / err[2] > 3.5);
    CHECK(err[1] / err[2] < 4.5);
  }
}

TEST_CASE("Square duct: kappa against the series solution, converging with resolution") {
  double err[2];
  int k = 0;
  for (int a : {8, 16}) {
    const FlowObservables o = steady(channel(2, a, 0, 1, true, a), settings("mrt", 1.0, Driving::kBodyForce), 1e-10);
    err[k++] = std::abs(o.kappa_lu / duct_kappa(a) - 1);
  }
  INFO("errors " << err[0] << " " << err[1]);
  CHECK(err[1] < 0.01);
  CHECK(err[0] / err[1] > 3);
}

TEST_CASE("Square duct: with MRT and TRT kappa does not depend on tau, with BGK it does") {
  const PoreLattice p = channel(2, 8, 0, 1, true, 8);
  for (const char* style : {"mrt", "trt", "bgk"}) {
    const double spread = tau_spread(p, style, {0.6, 1.0, 1.5}, Driving::kBodyForce, 1e-10);
    INFO(style << " spread " << spread);
    if (std::string(style) == "bgk") CHECK(spread > 0.02);
    else CHECK(spread < 1e-4);
  }
}

TEST_CASE("Poiseuille: with MRT and TRT kappa does not depend on tau, with BGK it does") {
  const PoreLattice p = channel(4, 6, 0, 1);
  for (const char* style : {"mrt", "trt", "bgk"}) {
    const double spread = tau_spread(p, style, {0.6, 0.8, 1.0, 1.5, 2.0}, Driving::kBodyForce, 1e-9);
    INFO(style << " spread " << spread);
    if (std::string(style) == "bgk") CHECK(spread > 0.05);
    else CHECK(spread < 1e-6);
  }
}

TEST_CASE("porous box: with TRT and MRT (ghost rates scaled with tau) kappa does not depend on tau") {
  PoreLattice p = periodic_spheres(20, 16, 16, {{4, 4, 4, 4.5}, {12, 10, 6, 5}, {7, 12, 13, 4}, {16, 3, 11, 3.5}, {2, 9, 9, 3}});
  p.wall_fraction = nullptr;
  // Down to the tau of lbflow's default: d'Humieres's ghost rates held fixed moved this kappa by
  // 1.5 % between tau = 0.8 and 1.5 and a jammed cluster's by 30 % from tau = 1 to 0.52.
  for (const char* style : {"trt", "mrt"}) {
    const double spread = tau_spread(p, style, {0.55, 0.8, 1.0, 1.5}, Driving::kBodyForce, 1e-9);
    INFO(style << " spread " << spread);
    CHECK(spread < 1e-4);
  }
  const double held = tau_spread(p, "mrt-dh", {0.8, 1.0}, Driving::kPressure, 1e-9);
  INFO("mrt-dh spread " << held);
  CHECK(held > 1e-3);
}
