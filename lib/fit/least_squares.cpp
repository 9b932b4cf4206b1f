#include "fit/least_squares.hpp"

#include "core/errors.hpp"

#include <Eigen/SVD>
#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace cmp::fit {

namespace {

// GSL's default error handler aborts the program; errors come back as status codes instead.
void quiet_gsl() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

// The change of variables p(u) of least_squares.hpp and its derivative.
struct Transform {
  double lo, hi;
  double p(double u) const {
    if (std::isfinite(lo) && std::isfinite(hi)) return lo + (hi - lo) / (1 + std::exp(-u));
    if (std::isfinite(lo)) return lo + std::exp(u);
    if (std::isfinite(hi)) return hi - std::exp(u);
    return u;
  }
  double dp(double u) const {
    if (std::isfinite(lo) && std::isfinite(hi)) {
      const double s = 1 / (1 + std::exp(-u));
      return (hi - lo) * s * (1 - s);
    }
    if (std::isfinite(lo)) return std::exp(u);
    if (std::isfinite(hi)) return -std::exp(u);
    return 1.0;
  }
  // Inverse; a value on or beyond a bound is moved just inside it.
  double u(double p) const {
    if (std::isfinite(lo) && std::isfinite(hi)) {
      const double s = std::clamp((p - lo) / (hi - lo), 1e-9, 1 - 1e-9);
      return std::log(s / (1 - s));
    }
    if (std::isfinite(lo)) return std::log(std::max(p - lo, 1e-6 * std::max(1.0, std::abs(lo))));
    if (std::isfinite(hi)) return std::log(std::max(hi - p, 1e-6 * std::max(1.0, std::abs(hi))));
    return p;
  }
};

// Residuals larger than any a fit produces, for trial points where the model is undefined
// (ln of a non-positive value): the trust region rejects such steps and shrinks.
constexpr double kHuge = 1e100;

// The model in the loss's space: f, or ln f for the log loss; and its gradient.
double model_term(const Model& m, Loss loss, double x, const double* p) {
  if (loss != Loss::Log) return m.value(x, p);
  if (m.log_value) return m.log_value(x, p);
  const double f = m.value(x, p);
  return f > 0 ? std::log(f) : std::numeric_limits<double>::quiet_NaN();
}
void model_term_gradient(const Model& m, Loss loss, double x, const double* p, double* g) {
  if (loss == Loss::Log && m.log_gradient) return m.log_gradient(x, p, g);
  m.gradient(x, p, g);
  if (loss != Loss::Log) return;
  const double f = m.value(x, p);
  for (std::size_t k = 0; k < m.params.size(); ++k) g[k] /= f;
}

// The weight 1 / sigma_i of point i (1 when the problem is unweighted).
double weight(const Problem& pr, std::size_t i) { return pr.weight.empty() ? 1.0 : pr.weight[i]; }

struct Context {
  const Problem* problem;
  std::vector<Transform> transforms;  // per free parameter
  std::vector<double> p;              // scratch: all parameters
  std::vector<double> grad;           // scratch: gradient in all parameters
  std::vector<double> target;         // y, or ln y for the log loss

  void set(const gsl_vector* u) {
    for (std::size_t k = 0; k < transforms.size(); ++k)
      p[problem->free[k]] = transforms[k].p(gsl_vector_get(u, k));
  }
};

int residuals(const gsl_vector* u, void* data, gsl_vector* r) {
  auto& c = *static_cast<Context*>(data);
  c.set(u);
  const auto& pr = *c.problem;
  const double huge = kHuge / std::sqrt(static_cast<double>(pr.x.size()));
  for (std::size_t i = 0; i < pr.x.size(); ++i) {
    const double ri = (model_term(*pr.model, pr.loss, pr.x[i], c.p.data()) - c.target[i]) * weight(pr, i);
    gsl_vector_set(r, i, std::isfinite(ri) ? ri : huge);
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* u, void* data, gsl_matrix* J) {
  auto& c = *static_cast<Context*>(data);
  c.set(u);
  const auto& pr = *c.problem;
  for (std::size_t i = 0; i < pr.x.size(); ++i) {
    model_term_gradient(*pr.model, pr.loss, pr.x[i], c.p.data(), c.grad.data());
    for (std::size_t k = 0; k < c.transforms.size(); ++k) {
      const double g = c.grad[pr.free[k]] * c.transforms[k].dp(gsl_vector_get(u, k)) * weight(pr, i);
      gsl_matrix_set(J, i, k, std::isfinite(g) ? g : 0.0);
    }
  }
  return GSL_SUCCESS;
}

struct Attempt {
  bool converged = false;
  double cost = std::numeric_limits<double>::infinity();
  std::vector<double> p;
  int iterations = 0;
  std::string status;
};

Attempt run_from(const Problem& pr, const std::vector<double>& start) {
  const std::size_t n = pr.x.size(), k = pr.free.size();
  Context c{&pr, {}, start, std::vector<double>(start.size()), pr.y};
  if (pr.loss == Loss::Log)
    for (double& t : c.target) t = std::log(t);
  for (int idx : pr.free) c.transforms.push_back({pr.lower[idx], pr.upper[idx]});

  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = jacobian;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = k;
  fdf.params = &c;
  auto params = gsl_multifit_nlinear_default_parameters();
  params.trs = gsl_multifit_nlinear_trs_lm;
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, k);
  gsl_vector* u0 = gsl_vector_alloc(k);
  for (std::size_t j = 0; j < k; ++j) gsl_vector_set(u0, j, c.transforms[j].u(start[pr.free[j]]));

  Attempt a;
  int status = gsl_multifit_nlinear_init(u0, &fdf, w);
  // Tight tolerances (fits are tiny): stop on a relative step below 1e-14 or a vanishing
  // gradient; a step that cannot lower the cost any more (GSL_ENOPROG) after progress was
  // made means the minimum is reached to machine precision.
  constexpr double xtol = 1e-11, gtol = 1e-12;
  int info = 0;
  for (int iter = 1; status == GSL_SUCCESS && iter <= pr.max_iterations; ++iter) {
    a.iterations = iter;
    status = gsl_multifit_nlinear_iterate(w);
    if (status == GSL_ENOPROG) {
      int loose_info = 0;
      const bool small_gradient =
          gsl_multifit_nlinear_test(1e-8, 1e-8, 0.0, &loose_info, w) == GSL_SUCCESS;
      a.converged = iter > 1 || small_gradient;
      a.status = a.converged ? "converged (no further decrease)" : "no progress from the starting point";
      break;
    }
    if (status != GSL_SUCCESS) {
      a.status = std::string("solver error: ") + gsl_strerror(status);
      break;
    }
    if (gsl_multifit_nlinear_test(xtol, gtol, 0.0, &info, w) == GSL_SUCCESS) {
      a.converged = true;
      a.status = info == 1 ? "converged (small step)" : "converged (small gradient)";
      break;
    }
  }
  if (!a.converged && a.status.empty()) a.status = fmt::format("not converged in {} iterations", pr.max_iterations);
  c.set(gsl_multifit_nlinear_position(w));
  a.p = c.p;
  const gsl_vector* r = gsl_multifit_nlinear_residual(w);
  double cost = 0;
  gsl_blas_ddot(r, r, &cost);
  a.cost = cost;
  if (!std::isfinite(cost) || cost >= kHuge) a.converged = false;
  for (double v : a.p)
    if (!std::isfinite(v)) a.converged = false;
  gsl_vector_free(u0);
  gsl_multifit_nlinear_free(w);
  return a;
}

}  // namespace

Eigen::MatrixXd scaled_covariance(const Eigen::MatrixXd& J, const std::vector<int>& free, int total, double factor) {
  const int k = static_cast<int>(free.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(total, total);
  if (k == 0) return cov;
  // As scipy's curve_fit: pcov = V diag(1/s^2) V^T over s > eps max(n, k) s_0.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  const double cut = std::numeric_limits<double>::epsilon() * std::max<double>(J.rows(), k) * s(0);
  Eigen::VectorXd inv = Eigen::VectorXd::Zero(s.size());
  for (int j = 0; j < s.size(); ++j)
    if (s(j) > cut) inv(j) = 1 / (s(j) * s(j));
  const Eigen::MatrixXd V = svd.matrixV();
  const Eigen::MatrixXd small = V * inv.asDiagonal() * V.transpose() * factor;
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) cov(free[a], free[b]) = small(a, b);
  return cov;
}

Solution solve_least_squares(const Problem& pr) {
  quiet_gsl();
  const long n = static_cast<long>(pr.x.size());
  const int k = static_cast<int>(pr.free.size());
  Solution s;
  Attempt best;
  std::string last_status;
  for (const auto& start : pr.starts) {
    ++s.starts;
    Attempt a = k == 0 ? Attempt{true, 0.0, start, 0, "nothing to fit"} : run_from(pr, start);
    last_status = a.status;
    if (!a.converged) continue;
    ++s.starts_converged;
    if (k == 0) {
      a.cost = 0;
      for (long i = 0; i < n; ++i) {
        const double r = residual(*pr.model, pr.loss, pr.x[i], pr.y[i], a.p.data()) * weight(pr, i);
        a.cost += r * r;
      }
    }
    if (!best.converged || a.cost < best.cost) best = a;
  }
  if (!best.converged)
    throw ComputationError(fmt::format("the {} fit did not converge from any of {} starting points ({})",
                                       pr.model->name, s.starts, last_status));
  s.p = best.p;
  s.iterations = best.iterations;
  s.status = best.status;
  // Jacobian of the residuals in the original free parameters at the optimum.
  Eigen::MatrixXd J(n, k);
  std::vector<double> grad(s.p.size());
  for (long i = 0; i < n; ++i) {
    model_term_gradient(*pr.model, pr.loss, pr.x[i], s.p.data(), grad.data());
    for (int j = 0; j < k; ++j) J(i, j) = grad[pr.free[j]] * weight(pr, static_cast<std::size_t>(i));
  }
  if (n > k) {
    s.covariance = scaled_covariance(J, pr.free, static_cast<int>(s.p.size()), best.cost / static_cast<double>(n - k));
  } else {  // no residual variance to scale by: undefined, inf as curve_fit reports it
    s.covariance = Eigen::MatrixXd::Zero(static_cast<long>(s.p.size()), static_cast<long>(s.p.size()));
    for (int a : pr.free)
      for (int b : pr.free) s.covariance(a, b) = std::numeric_limits<double>::infinity();
  }
  return s;
}

}  // namespace cmp::fit
