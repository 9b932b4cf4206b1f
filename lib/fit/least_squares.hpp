#pragma once
// Non-linear least squares with GSL's multifit_nlinear: trust region with Levenberg-Marquardt
// steps, the model's analytic Jacobian, every starting point of the problem tried and the
// lowest converged cost kept.
//
// Bounds are kept by a smooth change of variables, so the solver itself is unconstrained:
//   p = u                               no bound
//   p = lo + exp(u)  /  p = hi - exp(u)  one bound (C > 0; phi_c < min x; width, beta > 0)
//   p = lo + (hi - lo) / (1 + exp(-u))  two bounds
// A bound is therefore never reached: a fit whose optimum lies on it stops short of it,
// reported by FitResult::at_bound. The covariance is computed in the original parameters
// from the Jacobian at the optimum, cov = (J^T J)^+ rss / (n - k), with the pseudo-inverse
// cut-off of scipy's curve_fit (singular values below eps max(n, k) s_max dropped), so that
// an interior optimum gives curve_fit's pcov (absolute_sigma=False). With weights 1/sigma_i
// (Problem::weight) every residual and Jacobian row is multiplied by its weight, as curve_fit
// does given sigma, and rss is then chi^2.
#include "fit/problem.hpp"

namespace cmp::fit {

// Throws cmp::ComputationError when no starting point converges.
Solution solve_least_squares(const Problem& problem);

// (J^T J)^+ of the residuals' Jacobian in the free parameters (n x k), embedded in the full
// parameter set (size total, zero rows/columns for the others), times factor.
Eigen::MatrixXd scaled_covariance(const Eigen::MatrixXd& jacobian, const std::vector<int>& free, int total,
                                  double factor);

}  // namespace cmp::fit
