#include "fit/fit_report.hpp"

#include "fit/group_fit.hpp"
#include "fit/plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::fit {

namespace {

// "name = value ± error" of parameter k.
std::string pm(const FitResult& r, std::size_t k, bool enhanced) {
  const std::string name = enhanced ? symbol(r.names[k]) : r.names[k];
  if (r.fixed[k]) return fmt::format("{} = {:.4g} (fixed)", name, r.value[k]);
  const double e = r.error[k];
  if (!(e > 0) || !std::isfinite(e)) return fmt::format("{} = {:.4g} ± {:.2g}", name, r.value[k], e);
  const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(e))), 0, 12);
  return fmt::format("{} = {:.{}f} ± {:.{}f}", name, r.value[k], decimals, e, decimals);
}

}  // namespace

std::string parameter_summary(const FitResult& r, bool enhanced) {
  std::string s;
  for (std::size_t k = 0; k < r.names.size(); ++k) s += (k ? ", " : "") + pm(r, k, enhanced);
  return s;
}

std::string goodness_summary(const FitResult& r, bool enhanced) {
  if (r.loss == Loss::MaxLikelihood)
    return fmt::format("ln L = {:.4g}, deviance = {:.4g}, McFadden pseudo-R^2 = {:.3f}", r.log_likelihood,
                       r.deviance, r.pseudo_r2);
  return fmt::format("R^2{} = {:.4f}, {}/dof = {:.3g}", r.loss == Loss::Log ? " (ln y)" : "", r.r2,
                     enhanced ? "{/Symbol c}^2" : "chi^2", r.chi2_dof);
}

void write_report_csv(io::CsvWriter& csv, const FitReport& report) {
  for (const auto& [key, value] : report.input_meta) csv.meta("input." + key, value);
  csv.meta("provenance", report.provenance);
  csv.meta("input", fmt::format("{}", fmt::join(report.inputs, " ")));
  csv.meta("model", report.model->name);
  csv.meta("formula", report.model->formula);
  csv.meta("loss", loss_name(report.loss));
  csv.meta("x", report.x);
  csv.meta("y", report.y);
  if (!report.sigma.empty()) csv.meta("sigma", report.sigma);
  if (report.sigma_zero)
    csv.meta("sigma_zero",
             fmt::format("{} zero errors replaced by the smallest positive one of their group", report.sigma_zero));
  if (!report.where.empty()) csv.meta("where", fmt::format("{}", fmt::join(report.where, " and ")));
  if (!report.group_by.empty()) csv.meta("group_by", fmt::format("{}", fmt::join(report.group_by, ",")));
  if (report.bootstrap > 0) csv.meta("bootstrap_seed", std::to_string(report.seed));
  if (report.kc_classical) csv.meta("kc_classical_C", io::format_number(*report.kc_classical));
  if (report.group_by.empty()) write_parameter_table(csv, report.fits[0].result, &report.fits[0].boot);
  else write_group_table(csv, report.group_by, report.fits);
}

std::string report_summary(const std::string& program, const FitReport& report) {
  std::string text;
  for (const auto& f : report.fits) {
    const auto& r = f.result;
    const std::string group = group_label(report.group_by, f.key);
    text += fmt::format("{}: {}{} ({} loss{}), {} points{}: {}; {}, AIC = {:.4g}; {}{}\n", program,
                        group.empty() ? "" : group + ": ", report.model->name, loss_name(report.loss),
                        r.weighted ? ", weighted" : "", r.n,
                        r.dropped ? fmt::format(" ({} dropped: {})", r.dropped, r.dropped_why) : "",
                        parameter_summary(r, false), goodness_summary(r, false), r.aic, r.status,
                        r.at_bound ? "; WARNING: a parameter ended on its bound" : "");
  }
  return text;
}

}  // namespace cmp::fit
