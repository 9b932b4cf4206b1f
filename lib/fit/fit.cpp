#include "fit/fit.hpp"

#include "core/errors.hpp"
#include "fit/least_squares.hpp"
#include "fit/logistic.hpp"
#include "fit/problem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cmp::fit {

std::string loss_name(Loss loss) {
  switch (loss) {
    case Loss::Linear: return "linear";
    case Loss::Log: return "log";
    case Loss::MaxLikelihood: return "ml";
  }
  return "?";
}

Loss parse_loss(const std::string& name) {
  if (name == "linear") return Loss::Linear;
  if (name == "log") return Loss::Log;
  if (name == "ml") return Loss::MaxLikelihood;
  throw UsageError("--loss: unknown loss '" + name + "'; losses: linear, log, ml");
}

double residual(const Model& model, Loss loss, double x, double y, const double* p) {
  if (loss == Loss::Log && model.log_value) return model.log_value(x, p) - std::log(y);
  const double f = model.value(x, p);
  switch (loss) {
    case Loss::Log: return f > 0 ? std::log(f) - std::log(y) : std::numeric_limits<double>::quiet_NaN();
    case Loss::MaxLikelihood: return y - f;
    case Loss::Linear: break;
  }
  return f - y;
}

namespace {

std::string parameter_list(const Model& m) {
  std::string s;
  for (const auto& p : m.params) s += (s.empty() ? "" : ", ") + p.name;
  return s;
}

// C of f = C g(x) that minimises the loss for the other parameters as given.
double best_scale(const Model& m, Loss loss, const std::vector<double>& x, const std::vector<double>& y,
                  std::vector<double> p) {
  p[m.scale] = 1.0;
  double num = 0, den = 0, sum_log = 0;
  long count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double g = m.value(x[i], p.data());
    if (!(g > 0) || !std::isfinite(g)) continue;
    num += y[i] * g, den += g * g;
    if (y[i] > 0) sum_log += std::log(y[i]) - std::log(g), ++count;
  }
  const double c = loss == Loss::Log ? (count > 0 ? std::exp(sum_log / count) : 1.0) : (den > 0 ? num / den : 1.0);
  return std::isfinite(c) && c > 0 ? c : 1.0;
}

}  // namespace

FitResult fit(const Model& m, const std::vector<double>& x_in, const std::vector<double>& y_in,
              const FitOptions& o, const std::vector<double>& sigma_in) {
  const int np = static_cast<int>(m.params.size());
  // Which parameters are fixed, at what.
  std::vector<bool> fixed(np);
  std::vector<double> fixed_value(np);
  for (int k = 0; k < np; ++k) fixed[k] = m.params[k].fixed_by_default, fixed_value[k] = m.params[k].start;
  for (const auto& name : o.freed) {
    const int k = m.index(name);
    if (k < 0)
      throw UsageError(fmt::format("--free: model {} has no parameter '{}'; its parameters: {}", m.name, name,
                                   parameter_list(m)));
    fixed[k] = false;
  }
  for (const auto& [name, value] : o.fixed) {
    const int k = m.index(name);
    if (k < 0)
      throw UsageError(fmt::format("--fix: model {} has no parameter '{}'; its parameters: {}", m.name, name,
                                   parameter_list(m)));
    fixed[k] = true, fixed_value[k] = value;
  }
  if (o.loss == Loss::MaxLikelihood && !m.probability)
    throw UsageError(fmt::format("--loss ml is for 0/1 outcomes and the sigmoid model, not {}", m.name));
  if (!sigma_in.empty() && o.loss != Loss::Linear)
    throw UsageError(fmt::format("--sigma weights the linear loss only, not --loss {}", loss_name(o.loss)));
  if (!sigma_in.empty() && sigma_in.size() != x_in.size())
    throw std::invalid_argument("fit: sigma needs one value per point");

  // The points in the domain.
  Problem pr;
  pr.model = &m;
  pr.loss = o.loss;
  pr.max_iterations = o.max_iterations;
  long out_x = 0, out_threshold = 0, out_y = 0;
  const bool threshold_fixed = m.threshold >= 0 && fixed[m.threshold];
  for (std::size_t i = 0; i < x_in.size(); ++i) {
    if (!m.x_in_domain(x_in[i])) { ++out_x; continue; }
    if (threshold_fixed && !(x_in[i] > fixed_value[m.threshold])) { ++out_threshold; continue; }
    if (o.loss == Loss::Log && !(y_in[i] > 0)) { ++out_y; continue; }
    pr.x.push_back(x_in[i]);
    pr.y.push_back(y_in[i]);
    if (!sigma_in.empty()) {
      if (!(sigma_in[i] > 0) || !std::isfinite(sigma_in[i]))
        throw std::invalid_argument("fit: every sigma must be positive and finite");
      pr.weight.push_back(1.0 / sigma_in[i]);
    }
  }
  FitResult r;
  r.model = m.name;
  r.loss = o.loss;
  r.dropped = out_x + out_threshold + out_y;
  std::vector<std::string> why;
  if (out_x) why.push_back(fmt::format("{} outside {}", out_x, m.domain));
  if (out_threshold)
    why.push_back(fmt::format("{} with x <= {} = {}", out_threshold, m.params[m.threshold].name,
                              fixed_value[m.threshold]));
  if (out_y) why.push_back(fmt::format("{} with y <= 0 (log loss)", out_y));
  for (const auto& w : why) r.dropped_why += (r.dropped_why.empty() ? "" : "; ") + w;
  const long n = static_cast<long>(pr.x.size());
  for (int k = 0; k < np; ++k)
    if (!fixed[k]) pr.free.push_back(k);
  const int nfree = static_cast<int>(pr.free.size());
  if (n == 0)
    throw ComputationError(fmt::format("no point lies in the domain of model {} ({}){}", m.name, m.domain,
                                       r.dropped_why.empty() ? "" : ": dropped " + r.dropped_why));
  if (n < nfree + 1)
    throw DegenerateFit(fmt::format("{} point{} for {} free parameters of model {}: a fit needs at least {}, one "
                                    "more than its free parameters (else chi2_dof is undefined){}",
                                    n, n == 1 ? "" : "s", nfree, m.name, nfree + 1,
                                    r.dropped_why.empty() ? "" : " (dropped " + r.dropped_why + ")"));
  const auto [x_lo, x_hi] = std::minmax_element(pr.x.begin(), pr.x.end());
  if (*x_lo == *x_hi)
    throw DegenerateFit(fmt::format("no spread in x: all {} points have x = {}{}", n, *x_lo,
                                    r.dropped_why.empty() ? "" : " (dropped " + r.dropped_why + ")"));
  const auto [y_lo, y_hi] = std::minmax_element(pr.y.begin(), pr.y.end());
  if (*y_lo == *y_hi)
    throw DegenerateFit(o.loss == Loss::MaxLikelihood
                            ? fmt::format("no spread in y: all {} outcomes are {}: no transition to fit", n, *y_lo)
                            : fmt::format("no spread in y: all {} points have y = {}{}", n, *y_lo,
                                          r.dropped_why.empty() ? "" : " (dropped " + r.dropped_why + ")"));

  // Bounds: the model's, and phi_c below the smallest x.
  for (int k = 0; k < np; ++k) pr.lower.push_back(m.params[k].lower), pr.upper.push_back(m.params[k].upper);
  if (m.threshold >= 0 && !fixed[m.threshold]) {
    const double min_x = *std::min_element(pr.x.begin(), pr.x.end());
    pr.upper[m.threshold] = std::min(pr.upper[m.threshold], min_x);
  }
  // Starting points: the user's or the model's, fixed values imposed, C from the data,
  // every value strictly inside its bounds.
  auto starts = o.start.empty() ? m.starts(pr.x, pr.y) : std::vector<std::vector<double>>{o.start};
  for (auto& s : starts) {
    s.resize(np, 1.0);
    for (int k = 0; k < np; ++k) {
      if (fixed[k]) { s[k] = fixed_value[k]; continue; }
      const double lo = pr.lower[k], hi = pr.upper[k];
      if (std::isfinite(hi) && s[k] >= hi) s[k] = std::isfinite(lo) ? 0.5 * (lo + hi) : hi - 0.05 * std::max(1.0, std::abs(hi));
      if (std::isfinite(lo) && s[k] <= lo) s[k] = std::isfinite(hi) ? 0.5 * (lo + hi) : lo + 0.05 * std::max(1.0, std::abs(lo));
    }
    if (m.scale >= 0 && !fixed[m.scale] && o.start.empty()) s[m.scale] = best_scale(m, o.loss, pr.x, pr.y, s);
    if (std::find(pr.starts.begin(), pr.starts.end(), s) == pr.starts.end()) pr.starts.push_back(s);
  }

  const Solution sol = o.loss == Loss::MaxLikelihood ? solve_logistic(pr) : solve_least_squares(pr);

  r.names.clear();
  for (const auto& p : m.params) r.names.push_back(p.name);
  r.value = sol.p;
  r.fixed = fixed;
  r.covariance = sol.covariance;
  r.error.resize(np);
  for (int k = 0; k < np; ++k) r.error[k] = fixed[k] ? 0.0 : std::sqrt(r.covariance(k, k));  // NaN if not >= 0
  r.n = n;
  r.free_parameters = nfree;
  r.iterations = sol.iterations;
  r.starts = sol.starts;
  r.starts_converged = sol.starts_converged;
  r.status = sol.status;
  for (int k : pr.free) {
    const double v = r.value[k];
    for (double b : {pr.lower[k], pr.upper[k]})
      if (std::isfinite(b) && std::abs(v - b) <= 1e-6 * std::max(1.0, std::abs(b))) r.at_bound = true;
  }
  // Statistics in the loss's space (ln y for Log, y otherwise), of the weighted residuals.
  auto w2 = [&](long i) { return pr.weight.empty() ? 1.0 : pr.weight[i] * pr.weight[i]; };
  auto target = [&](long i) { return o.loss == Loss::Log ? std::log(pr.y[i]) : pr.y[i]; };
  double mean = 0, wsum = 0;
  for (long i = 0; i < n; ++i) mean += w2(i) * target(i), wsum += w2(i);
  mean /= wsum;
  double rss = 0, tss = 0;
  for (long i = 0; i < n; ++i) {
    const double res = residual(m, o.loss, pr.x[i], pr.y[i], r.value.data());
    const double dev = target(i) - mean;
    rss += w2(i) * res * res, tss += w2(i) * dev * dev;
  }
  r.weighted = !pr.weight.empty();
  r.rss = rss;
  r.r2 = tss > 0 ? 1 - rss / tss : std::numeric_limits<double>::quiet_NaN();
  r.chi2_dof = n > nfree ? rss / static_cast<double>(n - nfree) : std::numeric_limits<double>::quiet_NaN();
  if (o.loss == Loss::MaxLikelihood) {
    r.log_likelihood = sol.log_likelihood;
    r.aic = 2.0 * nfree - 2.0 * sol.log_likelihood;
    r.deviance = -2.0 * sol.log_likelihood;
    double ones = 0;
    for (double v : pr.y) ones += v;
    const double p = ones / static_cast<double>(n);
    r.null_log_likelihood = (ones > 0 ? ones * std::log(p) : 0.0) + (n - ones > 0 ? (n - ones) * std::log1p(-p) : 0.0);
    r.pseudo_r2 = r.null_log_likelihood < 0 ? 1 - sol.log_likelihood / r.null_log_likelihood
                                            : std::numeric_limits<double>::quiet_NaN();
  } else {
    r.aic = static_cast<double>(n) * std::log(rss / static_cast<double>(n)) + 2.0 * nfree;
  }
  // No statistic is written that is not a number: anything non-finite is a failed fit, but for
  // a perfect fit's AIC (rss 0: n ln 0), which the tables leave empty (fit_table.hpp).
  const std::vector<std::pair<const char*, double>> statistics =
      o.loss == Loss::MaxLikelihood
          ? std::vector<std::pair<const char*, double>>{{"log_likelihood", r.log_likelihood},
                                                        {"deviance", r.deviance},
                                                        {"pseudo_r2", r.pseudo_r2},
                                                        {"aic", r.aic}}
          : std::vector<std::pair<const char*, double>>{
                {"rss", r.rss}, {"r2", r.r2}, {"chi2_dof", r.chi2_dof}, {"aic", r.aic}};
  for (const auto& [name, value] : statistics)
    if (!std::isfinite(value) && !(std::string(name) == "aic" && r.rss == 0 && o.loss != Loss::MaxLikelihood))
      throw ComputationError(fmt::format("model {}: the fit's {} is {} (rss {}): no statistic to report", m.name,
                                         name, value, r.rss));
  return r;
}

}  // namespace cmp::fit
