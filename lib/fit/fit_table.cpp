#include "fit/fit_table.hpp"

#include <fmt/format.h>

#include <cmath>

namespace cmp::fit {

std::vector<std::pair<std::string, std::string>> goodness(const FitResult& r) {
  using io::format_number;
  if (r.loss == Loss::MaxLikelihood)
    return {{"log_likelihood", format_number(r.log_likelihood)},
            {"null_log_likelihood", format_number(r.null_log_likelihood)},
            {"deviance", format_number(r.deviance)},
            {"pseudo_r2", format_number(r.pseudo_r2)},
            {"aic", format_number(r.aic)}};
  // A perfect fit (rss 0) has no AIC (n ln 0): left empty rather than written as -inf.
  return {{"r2", format_number(r.r2)}, {"chi2_dof", format_number(r.chi2_dof)},
          {"aic", std::isfinite(r.aic) ? format_number(r.aic) : std::string()}};
}

void write_parameter_table(io::CsvWriter& csv, const FitResult& r, const BootstrapResult* boot) {
  using io::format_number;
  csv.meta("n", std::to_string(r.n));
  csv.meta("dropped", std::to_string(r.dropped));
  if (r.dropped) csv.meta("dropped_why", r.dropped_why);
  csv.meta("rss", format_number(r.rss));
  for (const auto& [key, value] : goodness(r)) csv.meta(key, value);
  csv.meta("status", r.status);
  csv.meta("iterations", std::to_string(r.iterations));
  csv.meta("starts", fmt::format("{} converged of {}", r.starts_converged, r.starts));
  csv.meta("at_bound", r.at_bound ? "1" : "0");
  const bool b = boot && boot->replicas > 0;
  if (b) {
    csv.meta("bootstrap", std::to_string(boot->replicas));
    csv.meta("bootstrap_failed", std::to_string(boot->failed));
  }
  std::vector<std::string> header{"parameter", "value", "stderr", "fixed"};
  for (const auto& n : r.names) header.push_back("cov_" + n);
  if (b)
    for (const char* h : {"bootstrap_mean", "bootstrap_stderr", "bootstrap_q025", "bootstrap_q975"}) header.push_back(h);
  csv.header(header);
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    std::vector<std::string> row{r.names[k], format_number(r.value[k]), format_number(r.error[k]), r.fixed[k] ? "1" : "0"};
    for (std::size_t j = 0; j < r.names.size(); ++j) row.push_back(format_number(r.covariance(k, j)));
    if (b)
      for (double v : {boot->mean[k], boot->stddev[k], boot->q025[k], boot->q975[k]}) row.push_back(format_number(v));
    csv.row(row);
  }
}

void write_group_table(io::CsvWriter& csv, const std::vector<std::string>& group_columns,
                       const std::vector<GroupFit>& fits) {
  using io::format_number;
  if (fits.empty()) return;
  const FitResult& first = fits.front().result;
  const bool b = fits.front().boot.replicas > 0;
  std::vector<std::string> header = group_columns;
  header.push_back("n");
  header.push_back("dropped");
  for (const auto& name : first.names) {
    header.push_back(name);
    header.push_back(name + "_error");
    if (b)
      for (const char* s : {"_bootstrap_stderr", "_bootstrap_q025", "_bootstrap_q975"}) header.push_back(name + s);
  }
  for (const auto& [key, value] : goodness(first)) header.push_back(key);
  header.push_back("at_bound");
  csv.header(header);
  for (const auto& g : fits) {
    const auto& r = g.result;
    std::vector<std::string> row = g.key;
    row.push_back(std::to_string(r.n));
    row.push_back(std::to_string(r.dropped));
    for (std::size_t k = 0; k < r.names.size(); ++k) {
      row.push_back(format_number(r.value[k]));
      row.push_back(format_number(r.error[k]));
      if (b)
        for (double v : {g.boot.stddev[k], g.boot.q025[k], g.boot.q975[k]}) row.push_back(format_number(v));
    }
    for (const auto& [key, value] : goodness(r)) row.push_back(value);
    row.push_back(r.at_bound ? "1" : "0");
    csv.row(row);
  }
}

}  // namespace cmp::fit
