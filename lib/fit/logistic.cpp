#include "fit/logistic.hpp"

#include "core/errors.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::fit {

namespace {

// ln(1 + e^z) without overflow.
double log1p_exp(double z) { return z > 0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z)); }

// Log-likelihood of outcomes y given log-odds a + b t.
double log_likelihood(const std::vector<double>& t, const std::vector<double>& y, double a, double b) {
  double l = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double z = a + b * t[i];
    l += y[i] * z - log1p_exp(z);
  }
  return l;
}

}  // namespace

Solution solve_logistic(const Problem& pr) {
  if (pr.free.size() != 2)
    throw UsageError("--loss ml fits both phi_c and width of the sigmoid; use --loss linear to fix one");
  const auto& x = pr.x;
  const auto& y = pr.y;
  const std::size_t n = x.size();
  double ones = 0, xmax0 = -kInf, xmin1 = kInf, xmin0 = kInf, xmax1 = -kInf;
  for (std::size_t i = 0; i < n; ++i) {
    if (y[i] != 0 && y[i] != 1)
      throw ComputationError(fmt::format("--loss ml needs outcomes 0 or 1; point {} has y = {}", i + 1, y[i]));
    ones += y[i];
    if (y[i] == 1) xmin1 = std::min(xmin1, x[i]), xmax1 = std::max(xmax1, x[i]);
    else xmax0 = std::max(xmax0, x[i]), xmin0 = std::min(xmin0, x[i]);
  }
  if (ones == 0 || ones == static_cast<double>(n))
    throw ComputationError(fmt::format("all {} outcomes are {}: no transition to fit", n, ones == 0 ? 0 : 1));
  if (xmax0 < xmin1 || xmax1 < xmin0)
    throw ComputationError(fmt::format(
        "the outcomes are perfectly separated (every 0 on one side of x = {} and every 1 on the other): the "
        "maximum-likelihood width is 0 and the threshold anywhere in the gap; the fit cannot converge "
        "(more samples near the threshold, or --loss linear on binned probabilities)",
        xmax0 < xmin1 ? 0.5 * (xmax0 + xmin1) : 0.5 * (xmax1 + xmin0)));

  // Standardised abscissa keeps Newton's method well conditioned.
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  double var = 0;
  for (double v : x) var += (v - mean) * (v - mean);
  const double sd = var > 0 ? std::sqrt(var / static_cast<double>(n)) : 1.0;
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = (x[i] - mean) / sd;

  Eigen::Vector2d theta(0, 0);
  double l = log_likelihood(t, y, 0, 0);
  Solution s;
  s.starts = 1;
  bool converged = false;
  Eigen::Matrix2d info;
  for (int iter = 1; iter <= pr.max_iterations; ++iter) {
    s.iterations = iter;
    Eigen::Vector2d grad(0, 0);
    info.setZero();
    for (std::size_t i = 0; i < n; ++i) {
      const double z = theta(0) + theta(1) * t[i];
      const double p = 1 / (1 + std::exp(-z));
      const Eigen::Vector2d v(1, t[i]);
      grad += (y[i] - p) * v;
      info += p * (1 - p) * v * v.transpose();
    }
    const Eigen::Vector2d step = info.ldlt().solve(grad);
    double h = 1;
    Eigen::Vector2d next = theta + step;
    double l_next = log_likelihood(t, y, next(0), next(1));
    while (!(l_next >= l) && h > 1e-10) {  // step halving keeps the likelihood rising
      h /= 2;
      next = theta + h * step;
      l_next = log_likelihood(t, y, next(0), next(1));
    }
    const double change = (next - theta).lpNorm<Eigen::Infinity>();
    theta = next;
    l = l_next;
    if (change < 1e-12 * std::max(1.0, theta.lpNorm<Eigen::Infinity>())) {
      converged = true;
      break;
    }
  }
  if (!converged || !std::isfinite(theta(1)) || theta(1) == 0)
    throw ComputationError(fmt::format("the maximum-likelihood sigmoid fit did not converge in {} iterations",
                                       pr.max_iterations));
  s.starts_converged = 1;
  s.status = "converged (Newton, maximum likelihood)";
  // Fisher information at the optimum.
  info.setZero();
  for (std::size_t i = 0; i < n; ++i) {
    const double p = 1 / (1 + std::exp(-(theta(0) + theta(1) * t[i])));
    const Eigen::Vector2d v(1, t[i]);
    info += p * (1 - p) * v * v.transpose();
  }
  const Eigen::Matrix2d cov_ab = info.inverse();
  const double a = theta(0), b = theta(1);
  // phi_c = mean - sd a / b, width = sd / b, and the delta method.
  Eigen::Matrix2d G;
  G << -sd / b, sd * a / (b * b), 0, -sd / (b * b);
  const Eigen::Matrix2d cov = G * cov_ab * G.transpose();
  s.p = {mean - sd * a / b, sd / b};
  s.covariance = cov;
  s.log_likelihood = l;
  if (s.p[1] <= 0)
    throw ComputationError("the maximum-likelihood sigmoid decreases with x (width < 0): outcomes of 1 lie "
                           "below those of 0");
  return s;
}

}  // namespace cmp::fit
