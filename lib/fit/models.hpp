#pragma once
// The laws of thesis Chapter 5 that kcfit fits (5.3.4, 5.5.4-5.5.6, Table S5.1), as one registry: a name, the
// parameters with their starting values and bounds, the value and its analytic gradient in
// the parameters, and the domain of the abscissa. kcfit --list-models prints this table.
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cmp::fit {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// One parameter of a model.
struct Parameter {
  std::string name;         // as typed in --fix, e.g. "phi_c"
  std::string meaning;      // one line for --list-models
  double start = 1.0;       // starting value when no data-driven start exists
  double lower = -kInf;     // bounds, kept by a smooth reparametrisation (least_squares.hpp)
  double upper = kInf;
  bool fixed_by_default = false;  // e.g. the tortuosity exponent -0.38; freed with --free
};

// A model y = f(x; p).
struct Model {
  std::string name;     // "kc-percolation"
  std::string formula;  // "C (x - phi_c)^(gamma + 0.76) x^2 / (1 - x)^2"
  std::string source;   // where in the thesis
  std::string title;    // the law as a figure title, gnuplot enhanced text ({/Symbol f} is phi)
  // Default CSV columns (the names percolate and lbflow write), first one present wins: e.g.
  // the sigmoid takes y from `percolates` (0/1 per packing) or else `probability` (percolate
  // sweep's fraction per bin).
  std::vector<std::string> x_columns, y_columns;
  std::vector<Parameter> params;
  // f(x; p); p has params.size() entries.
  std::function<double(double x, const double* p)> value;
  // grad[k] = d f / d p_k at (x, p).
  std::function<void(double x, const double* p, double* grad)> gradient;
  // Optional: ln f and its gradient in closed form (one logarithm instead of a power and a
  // logarithm: the log loss's hot path). ln f is NaN where f <= 0.
  std::function<double(double x, const double* p)> log_value;
  std::function<void(double x, const double* p, double* grad)> log_gradient;
  // Domain of x that does not depend on the parameters (e.g. 0 < phi < 1); points outside
  // it are dropped (and counted) before fitting.
  std::function<bool(double x)> x_in_domain;
  std::string domain;  // the same in words, for messages
  // Index of the threshold parameter phi_c with the constraint x > phi_c for every point
  // (an upper bound min x when free, dropped points x <= phi_c when fixed), or -1.
  int threshold = -1;
  // Index of a multiplicative constant C (f = C g(x; other parameters)), whose starting
  // value is then computed from the data in closed form, or -1.
  int scale = -1;
  // Starting points for the parameters other than C (values for all params; C's entry is
  // overwritten when scale >= 0), several where the fit may be multimodal. x is sorted-free
  // data; min_x is its minimum.
  std::function<std::vector<std::vector<double>>(const std::vector<double>& x, const std::vector<double>& y)>
      starts;
  // Whether the model is a probability in [0, 1] (the sigmoid), which allows the
  // maximum-likelihood loss for 0/1 outcomes.
  bool probability = false;
  // Columns of y that hold 0/1 outcomes (the sigmoid's `percolates`): any other value there is
  // bad input (fit_inputs.hpp, check_outcomes).
  std::vector<std::string> outcome_columns;

  // Index of the named parameter or -1.
  int index(const std::string& parameter) const;
};

// All models, in the order --list-models prints them.
const std::vector<Model>& models();

// The model of that name; throws cmp::UsageError listing the known names otherwise.
const Model& find_model(const std::string& name);

// Exponent 0.76 = -2 x (-0.38): tau_H^-2 with tau_H ~ (phi - phi_c)^-0.38 (thesis Eq. 5.8).
inline constexpr double kTortuosityExponent = -0.38;
// 2.52 = 1.76 + 0.76: the fixed-exponent form (model ii of Table S5.1 and 5.5.6, n_c ~ dphi^1.76 of 5.5.5).
inline constexpr double kFixedKcExponent = 2.52;

}  // namespace cmp::fit
