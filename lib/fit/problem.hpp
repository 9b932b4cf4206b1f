#pragma once
// A fit ready to solve, as fit() prepares it for the two solvers (least_squares.hpp,
// logistic.hpp): the points in the domain, the fixed values, the free parameters with their
// effective bounds (the threshold's upper bound is the smallest x) and the starting points.
#include "fit/fit.hpp"

#include <vector>

namespace cmp::fit {

struct Problem {
  const Model* model = nullptr;
  Loss loss = Loss::Linear;
  std::vector<double> x, y;                 // points in the domain
  std::vector<double> weight;               // 1 / sigma_i per point (least squares); empty: all 1
  std::vector<int> free;                    // indices of the fitted parameters
  std::vector<double> lower, upper;         // effective bounds of every parameter
  std::vector<std::vector<double>> starts;  // full parameter vectors (fixed values included)
  int max_iterations = 500;
};

// What a solver finds; fit() adds the statistics.
struct Solution {
  std::vector<double> p;        // all parameters
  Eigen::MatrixXd covariance;   // all parameters (zero rows/columns for fixed ones)
  double log_likelihood = 0;    // MaxLikelihood only
  int iterations = 0, starts = 0, starts_converged = 0;
  std::string status;
};

}  // namespace cmp::fit
