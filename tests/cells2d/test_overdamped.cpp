// The over-damped integrators on the linear test equation y' = lambda y: every registered
// style is stable up to the stability limit its table entry declares (which sets the chamber's
// default time step) and unstable beyond it; the Runge-Kutta-Chebyshev step is first order and
// damps stiff modes within each step.
#include "cells2d/overdamped.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace cmp::cells2d;

namespace {

// |y| after `steps` steps of y' = lambda y from y = 1 with lambda dt = z (z < 0).
double amplification(const IntegratorStyle& style, double z, int steps) {
  auto integrator = style.make();
  const double dt = 1e-3, lambda = z / dt;
  std::vector<double> y = {1.0};
  std::vector<char> fresh = {1};
  const VelocityField v = [lambda](const std::vector<double>& s, std::vector<double>& out) {
    out.resize(s.size());
    out[0] = lambda * s[0];
  };
  for (int k = 0; k < steps; ++k) integrator->step(y, dt, v, fresh);
  return std::abs(y[0]);
}

}  // namespace

TEST_CASE("overdamped integrators are stable exactly up to their declared stability limit", "[overdamped]") {
  for (const IntegratorStyle& style : integrator_styles()) {
    INFO(style.name << ", declared limit " << style.stability_limit);
    const double inside = amplification(style, -0.97 * style.stability_limit, 400);
    const double beyond = amplification(style, -1.05 * style.stability_limit, 400);
    CHECK(inside < 1.0);
    CHECK_FALSE(beyond <= 10.0);  // grown past 10, or overflowed to inf/NaN
  }
}

TEST_CASE("the Runge-Kutta-Chebyshev step: first order, 16 evaluations per step, stiff modes damped", "[overdamped]") {
  const IntegratorStyle& rkc = integrator_style("rkc");
  CHECK(rkc.stability_limit == Approx(321.9).epsilon(1e-3));  // beta_16 at damping 1: 1.26 s^2
  // y' = -y to t = 1: the error halves with dt.
  const auto error = [&](int steps) {
    auto integrator = rkc.make();
    std::vector<double> y = {1.0};
    std::vector<char> fresh;
    const VelocityField v = [](const std::vector<double>& s, std::vector<double>& out) { out = {-s[0]}; };
    for (int k = 0; k < steps; ++k) integrator->step(y, 1.0 / steps, v, fresh);
    CHECK(integrator->evaluations() == 16L * steps);
    return std::abs(y[0] - std::exp(-1.0));
  };
  const double e10 = error(10), e20 = error(20), e40 = error(40);
  CHECK(e20 / e10 == Approx(0.5).margin(0.03));
  CHECK(e40 / e20 == Approx(0.5).margin(0.03));
  // Across the stiff part of the interval one step multiplies a mode by at most 1 / T_s(w0).
  for (double z = -0.1 * rkc.stability_limit; z > -rkc.stability_limit; z -= 0.01 * rkc.stability_limit)
    CHECK(amplification(rkc, z, 1) < 0.47);
}
