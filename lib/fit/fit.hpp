#pragma once
// Fitting one model of models.hpp to (x, y) data, the way thesis 5.5.6 does with scipy:
// least squares on y (Loss::Linear) or on log y (Loss::Log, Table S5.1's log error function),
// standard errors from the covariance scaled by the residual variance (scipy curve_fit's
// default, absolute_sigma=False); or, for 0/1 outcomes and the sigmoid, maximum likelihood
// (Loss::MaxLikelihood, logistic regression).
#include "core/errors.hpp"
#include "fit/models.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace cmp::fit {

enum class Loss {
  Linear,        // sum (f(x_i) - y_i)^2
  Log,           // sum (ln f(x_i) - ln y_i)^2; the base of the logarithm changes nothing
  MaxLikelihood  // - sum ln P(y_i | x_i), y_i in {0, 1}, f the probability (sigmoid only)
};
std::string loss_name(Loss loss);  // "linear", "log", "ml"
// Parses "linear", "log", "ml"; throws cmp::UsageError naming --loss otherwise.
Loss parse_loss(const std::string& name);

// Data that no fit can describe, whatever the solver does: fewer points than free parameters
// plus one (chi2_dof undefined), or no spread in x or in y (the threshold, the exponent or r2
// undefined). A ComputationError (a bootstrap replica drawn degenerate just fails), which
// kcfit reports as bad input, exit 2, naming its file (group_fit.hpp).
class DegenerateFit : public ComputationError {
 public:
  using ComputationError::ComputationError;
};

struct FitOptions {
  Loss loss = Loss::Linear;
  // Parameters held at a value (--fix name=value); all others are fitted.
  std::vector<std::pair<std::string, double>> fixed;
  // Parameters fixed by default that are fitted instead (--free e for the tortuosity).
  std::vector<std::string> freed;
  // Iterations of the trust-region solver per starting point.
  int max_iterations = 500;
  // One starting point for every parameter (fixed ones ignored); empty: the model's starts.
  std::vector<double> start;
};

struct FitResult {
  std::string model;
  Loss loss = Loss::Linear;
  std::vector<std::string> names;    // parameter names, model order
  std::vector<double> value;         // best fit (the fixed value for fixed parameters)
  std::vector<double> error;         // standard error sqrt(cov_kk); 0 for fixed parameters
  std::vector<bool> fixed;
  Eigen::MatrixXd covariance;        // names.size() squared; rows/columns of fixed ones are 0
  long n = 0;                        // points fitted
  long dropped = 0;                  // points outside the model's domain (or y <= 0 for Log)
  std::string dropped_why;           // what the dropped points violated, "" if none
  int free_parameters = 0;
  bool weighted = false;             // least squares weighted by 1 / sigma_i
  double rss = 0;                    // residual sum of squares in the loss's space (ln y for Log),
                                     // of the weighted residuals (f - y) / sigma when weighted: chi^2
  double r2 = 0;                     // 1 - rss / tss in the same space (least squares; weighted
                                     // residuals and weighted mean when weighted)
  double chi2_dof = 0;               // rss / (n - k), the reduced chi^2 (residual variance when
                                     // unweighted); NaN when n == k
  double aic = 0;                    // n ln(rss / n) + 2k (least squares; -inf when rss = 0); 2k - 2 ln L (ML)
  // Maximum likelihood only:
  double log_likelihood = 0;         // ln L at the optimum
  double null_log_likelihood = 0;    // ln L of the constant probability (the fraction of ones)
  double deviance = 0;               // -2 ln L (the saturated model of 0/1 outcomes has ln L = 0)
  double pseudo_r2 = 0;              // McFadden's 1 - ln L / ln L_0 (0: no better than a constant)
  int iterations = 0;                // of the best start
  int starts = 0, starts_converged = 0;
  bool at_bound = false;             // a bounded parameter ended within 1e-6 relative of its bound
  std::string status;                // "converged (small step)", ...
};

// Fits model to the points (x_i, y_i). Points outside the model's domain (Model::x_in_domain,
// x <= phi_c for a fixed threshold, y <= 0 for the log loss) are dropped and counted.
// sigma (empty, or one positive finite value per point): standard errors of y, the least
// squares then weighted by 1 / sigma_i (curve_fit's sigma, absolute_sigma=False); only with
// the linear loss.
// Throws cmp::UsageError for a --fix/--free naming no parameter of the model or a loss the
// model does not support (sigma with another loss than linear); cmp::ComputationError when no
// point is left, fewer points than free parameters remain, or no starting point converges.
FitResult fit(const Model& model, const std::vector<double>& x, const std::vector<double>& y,
              const FitOptions& options, const std::vector<double>& sigma = {});

// Residual of one point in the loss's space: f - y, ln f - ln y, or y - f for MaxLikelihood.
double residual(const Model& model, Loss loss, double x, double y, const double* p);

}  // namespace cmp::fit
