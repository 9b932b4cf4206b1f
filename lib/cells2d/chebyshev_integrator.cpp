// The damped first-order Runge-Kutta-Chebyshev step (Verwer, Hundsdorfer and Sommeijer,
// Numer. Math. 57, 157 (1990); Verwer, Sommeijer and Hundsdorfer, J. Comput. Phys. 201, 61
// (2004)): s evaluations per step whose stability polynomial is a shifted Chebyshev polynomial,
// P_s(z) = T_s(w0 + w1 z) / T_s(w0), stable for z in [-beta_s, 0] with beta_s ~ s^2.
//
// Why it suits the chamber: over-damped motion of conservative contacts has a real, non-positive
// spectrum (the Hessian weighted by the positive mobilities), spread from the slow growth-driven
// modes to the stiff contact modes at about 10 mu k. Euler's step is held to 2 / (10 mu k) per
// evaluation; this one reaches beta_s / s per evaluation, ten times as far at s = 16, for the
// same first-order accuracy in the slow modes. The damping eps keeps |P_s| <= 1 / T_s(w0) (0.46
// at eps = 1) away from z = 0, so stiff contact modes decay within each step instead of ringing
// at the edge of stability.
#include "cells2d/overdamped.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>

namespace cmp::cells2d {

namespace {

constexpr int kStages = 16;
constexpr double kDamping = 1.0;

// The recurrence coefficients of the stages and the stability interval, from T_j(w0), T_j'(w0).
struct ChebyshevCoefficients {
  std::array<double, kStages + 1> mu{}, nu{}, mu_tilde{};
  double beta = 0;

  ChebyshevCoefficients() {
    const double w0 = 1 + kDamping / (kStages * kStages);
    std::array<double, kStages + 1> t{}, dt{};
    t[0] = 1, t[1] = w0, dt[0] = 0, dt[1] = 1;
    for (int j = 2; j <= kStages; ++j) {
      t[j] = 2 * w0 * t[j - 1] - t[j - 2];
      dt[j] = 2 * t[j - 1] + 2 * w0 * dt[j - 1] - dt[j - 2];
    }
    const double w1 = t[kStages] / dt[kStages];
    // b_j = 1 / T_j(w0); Y_j = mu_j Y_{j-1} + nu_j Y_{j-2} + mu~_j dt v(Y_{j-1}).
    mu_tilde[1] = w1 / w0;
    for (int j = 2; j <= kStages; ++j) {
      mu[j] = 2 * w0 * t[j - 1] / t[j];
      nu[j] = -t[j - 2] / t[j];
      mu_tilde[j] = 2 * w1 * t[j - 1] / t[j];
    }
    beta = (1 + w0) / w1;  // where w0 + w1 z = -1
  }
};

const ChebyshevCoefficients& coefficients() {
  static const ChebyshevCoefficients c;
  return c;
}

class Chebyshev final : public OverdampedIntegrator {
 public:
  void step(std::vector<double>& y, double dt, const VelocityField& v, std::vector<char>& fresh) override {
    const auto& c = coefficients();
    const std::size_t n = y.size();
    previous_ = y;  // Y_{j-2}
    velocity_.resize(n);
    v(y, velocity_);
    current_.resize(n);  // Y_{j-1}
    for (std::size_t i = 0; i < n; ++i) current_[i] = y[i] + c.mu_tilde[1] * dt * velocity_[i];
    for (int j = 2; j <= kStages; ++j) {
      v(current_, velocity_);
      for (std::size_t i = 0; i < n; ++i) {
        const double next = c.mu[j] * current_[i] + c.nu[j] * previous_[i] + c.mu_tilde[j] * dt * velocity_[i];
        previous_[i] = current_[i];
        current_[i] = next;
      }
    }
    evaluations_ += kStages;
    y.swap(current_);
    std::fill(fresh.begin(), fresh.end(), 0);  // no history to start
  }
  void compact(const std::vector<char>&) override {}
  std::vector<double> history() const override { return {}; }
  void set_history(std::vector<double>) override {}

 private:
  std::vector<double> previous_, current_, velocity_;
};

}  // namespace

std::unique_ptr<OverdampedIntegrator> make_chebyshev_integrator() { return std::make_unique<Chebyshev>(); }

double chebyshev_stability_limit() { return coefficients().beta; }

}  // namespace cmp::cells2d
