#pragma once
// Integrators of over-damped motion y' = v(y) (thesis S2.11-S2.12: r' = mu F, theta' = (m/I) mu T)
// for the chamber of Chapter 2, as styles: the thesis's Gear predictor-corrector ("3rd order":
// three values, and the four-value variant, since the text does not say which) and the explicit
// Euler step, so that their trajectories can be compared as dt -> 0.
//
// Gear's methods carry a Nordsieck history per degree of freedom: y, y1 = dt y', y2 = dt^2 y''/2
// (and y3 = dt^3 y'''/6). A step predicts with the Taylor (Pascal) matrix, evaluates v once at
// the prediction and corrects every value by c_k (dt v - y1_predicted); for a first-order
// equation the coefficients are (5/12, 1, 1/2) with three values and (3/8, 1, 3/4, 1/6) with four
// (Allen & Tildesley, Appendix E). A degree of freedom that has just appeared (a new cell) starts
// with y1 = dt v(y) and no higher terms.
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cmp::cells2d {

// v(y): fills velocity (same size as state) from state.
using VelocityField = std::function<void(const std::vector<double>& state, std::vector<double>& velocity)>;

class OverdampedIntegrator {
 public:
  virtual ~OverdampedIntegrator() = default;
  // Advances state by dt. fresh[i] marks degrees of freedom without a history (new cells; a
  // missing entry at the end counts as fresh); the integrator clears the marks.
  virtual void step(std::vector<double>& state, double dt, const VelocityField& v, std::vector<char>& fresh) = 0;
  // Degrees of freedom were removed: keep only those with keep[i] (the order is kept).
  virtual void compact(const std::vector<char>& keep) = 0;
  // The history, for checkpoints.
  virtual std::vector<double> history() const = 0;
  virtual void set_history(std::vector<double> h) = 0;
  void set_history(std::vector<double> h, long evaluations) {
    set_history(std::move(h));
    evaluations_ = evaluations;
  }
  // Force evaluations so far.
  long evaluations() const { return evaluations_; }

 protected:
  long evaluations_ = 0;
};

struct IntegratorStyle {
  const char* name;
  const char* description;
  std::unique_ptr<OverdampedIntegrator> (*make)();
  // The largest |lambda dt| for which the method is stable on y' = lambda y, lambda < 0 (2 for
  // Euler; 0.546 and 0.301 for Gear's three- and four-value correctors, from the eigenvalues of
  // their predict-correct matrices): the time step must keep the stiffest relaxation rate of the
  // cells, about 10 mu k in a dense packing, below it.
  double stability_limit;
};

const std::vector<IntegratorStyle>& integrator_styles();

// The damped Runge-Kutta-Chebyshev style (chebyshev_integrator.cpp): its integrator and its
// stability interval beta_s.
std::unique_ptr<OverdampedIntegrator> make_chebyshev_integrator();
double chebyshev_stability_limit();
// Throws cmp::UsageError "unknown integrator 'x' (known: ...)".
const IntegratorStyle& integrator_style(const std::string& name);

}  // namespace cmp::cells2d
