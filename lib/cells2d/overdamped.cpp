#include "cells2d/overdamped.hpp"

#include "core/registry.hpp"

#include <algorithm>
#include <array>

namespace cmp::cells2d {

namespace {

class Euler final : public OverdampedIntegrator {
 public:
  void step(std::vector<double>& y, double dt, const VelocityField& v, std::vector<char>& fresh) override {
    velocity_.resize(y.size());
    v(y, velocity_);
    ++evaluations_;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += dt * velocity_[i];
    std::fill(fresh.begin(), fresh.end(), 0);
  }
  void compact(const std::vector<char>&) override {}
  std::vector<double> history() const override { return {}; }
  void set_history(std::vector<double>) override {}

 private:
  std::vector<double> velocity_;
};

// Nordsieck form with Values values per degree of freedom (y itself is the state).
template <int Values>
class Gear final : public OverdampedIntegrator {
 public:
  void step(std::vector<double>& y, double dt, const VelocityField& v, std::vector<char>& fresh) override {
    const std::size_t n = y.size();
    // Degrees of freedom appended since the last step have no history: the caller marks them.
    if (h_.size() != (Values - 1) * n) h_.resize((Values - 1) * n, 0.0);
    if (fresh.size() != n) fresh.resize(n, 1);
    velocity_.resize(n);
    bool any_fresh = false;
    for (char f : fresh) any_fresh |= f != 0;
    if (any_fresh) {
      v(y, velocity_);
      ++evaluations_;
      for (std::size_t i = 0; i < n; ++i)
        if (fresh[i]) {
          double* h = &h_[(Values - 1) * i];
          h[0] = dt * velocity_[i];
          for (int k = 1; k < Values - 1; ++k) h[k] = 0;
          fresh[i] = 0;
        }
    }
    // Predict: y_k <- sum_{j >= k} C(j, k) y_j (the Pascal matrix).
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, Values> z;
      z[0] = y[i];
      for (int k = 1; k < Values; ++k) z[k] = h_[(Values - 1) * i + static_cast<std::size_t>(k - 1)];
      for (int k = 0; k < Values - 1; ++k)
        for (int j = Values - 1; j > k; --j) z[j - 1] += z[j];
      y[i] = z[0];
      for (int k = 1; k < Values; ++k) h_[(Values - 1) * i + static_cast<std::size_t>(k - 1)] = z[k];
    }
    v(y, velocity_);
    ++evaluations_;
    // Correct.
    constexpr std::array<double, 4> corrector =
        Values == 3 ? std::array<double, 4>{5.0 / 12, 1.0, 0.5, 0.0} : std::array<double, 4>{3.0 / 8, 1.0, 0.75, 1.0 / 6};
    for (std::size_t i = 0; i < n; ++i) {
      double* h = &h_[(Values - 1) * i];
      const double error = dt * velocity_[i] - h[0];
      y[i] += corrector[0] * error;
      for (int k = 1; k < Values; ++k) h[k - 1] += corrector[k] * error;
    }
  }

  void compact(const std::vector<char>& keep) override {
    std::size_t out = 0;
    for (std::size_t i = 0; i < keep.size(); ++i) {
      if (!keep[i]) continue;
      for (int k = 0; k < Values - 1; ++k) h_[(Values - 1) * out + k] = h_[(Values - 1) * i + k];
      ++out;
    }
    h_.resize((Values - 1) * out);
  }
  std::vector<double> history() const override { return h_; }
  void set_history(std::vector<double> h) override { h_ = std::move(h); }

 private:
  static_assert(Values == 3 || Values == 4);
  std::vector<double> h_;
  std::vector<double> velocity_;
};

}  // namespace

const std::vector<IntegratorStyle>& integrator_styles() {
  static const std::vector<IntegratorStyle> table = {
      {"gear3", "Gear predictor-corrector, three values (y, dt y', dt^2 y''/2), corrector (5/12, 1, 1/2)",
       [] { return std::unique_ptr<OverdampedIntegrator>(new Gear<3>); }, 0.546},
      {"gear4", "Gear predictor-corrector, four values, corrector (3/8, 1, 3/4, 1/6)",
       [] { return std::unique_ptr<OverdampedIntegrator>(new Gear<4>); }, 0.301},
      {"euler", "explicit Euler step y += dt v(y): first order, one evaluation per step",
       [] { return std::unique_ptr<OverdampedIntegrator>(new Euler); }, 2.0},
      {"rkc", "damped Runge-Kutta-Chebyshev step, 16 evaluations per step stable over a 160 times longer interval than "
              "Euler's: first order, ten times fewer evaluations for stiff contacts (long runs)",
       make_chebyshev_integrator, chebyshev_stability_limit()},
  };
  return table;
}

const IntegratorStyle& integrator_style(const std::string& name) {
  return find_style(integrator_styles(), name, "integrator");
}

}  // namespace cmp::cells2d
