#include "fit/fit_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::fit {

FitFigure fit_figure(const FitReport& report, const std::vector<GroupData>& data, const std::string& x_label,
                     const std::string& y_label, bool with_classical) {
  const Model& model = *report.model;
  const auto& fits = report.fits;
  const bool grouped = !report.group_by.empty();
  FitFigure figure;
  PlotSpec& spec = figure.spec;
  spec.x_label = x_label.empty() ? axis_label(report.x) : x_label;
  spec.y_label = y_label.empty() ? axis_label(report.y) : y_label;
  spec.log_y = report.loss == Loss::Log;
  spec.probability = model.probability;
  const bool ml = report.loss == Loss::MaxLikelihood;
  const std::string how = ml ? "maximum likelihood on 0/1 outcomes"
                             : fmt::format("least squares ({} loss{})", loss_name(report.loss),
                                           report.sigma.empty() ? "" : ", weighted by " + report.sigma);
  std::vector<std::string> group_symbols;
  for (const auto& g : report.group_by) group_symbols.push_back(symbol(g));
  spec.title = model.title + "\n{/*0.8 " + enhanced_literal(how) +
               (grouped ? fmt::format(", one fit per {}", fmt::join(group_symbols, " and "))
                        : fmt::format(", n = {}: {}", fits[0].result.n, goodness_summary(fits[0].result, true))) +
               "}";
  for (std::size_t g = 0; g < fits.size(); ++g) {
    const auto& r = fits[g].result;
    const auto& d = data[g];
    std::string label;
    for (std::size_t k = 0; k < report.group_by.size(); ++k)
      label += fmt::format("{}{} = {}", k ? ", " : "", symbol(report.group_by[k]), fits[g].key[k]);
    PlotPoints pts;
    if (ml) {
      const int bins = std::clamp(static_cast<int>(std::lround(std::sqrt(d.x.size() / 2.0))), 4, 20);
      pts = binned_outcomes(d.x, d.y, bins);
      pts.title = grouped ? "" : fmt::format("fraction per bin of {} (68 % binomial interval)", bins);
    } else {
      pts.x = d.x, pts.y = d.y;
      for (std::size_t i = 0; i < d.sigma.size(); ++i)
        pts.low.push_back(d.y[i] - d.sigma[i]), pts.high.push_back(d.y[i] + d.sigma[i]);
      pts.title = grouped ? "" : "data";
    }
    spec.points.push_back(pts);
    PlotCurve curve{&model, r.value, "", 0, 1, static_cast<int>(g), false};
    curve.title = grouped ? label + ": " + parameter_summary(r, true) +
                                (ml ? fmt::format(", pseudo-R^2 = {:.2f}", r.pseudo_r2) : "")
                          : "fit: " + parameter_summary(r, true);
    const double lo = *std::min_element(d.x.begin(), d.x.end()), hi = *std::max_element(d.x.begin(), d.x.end());
    curve.from = model.name == "threshold" ? 0.0 : lo, curve.to = hi;
    if (model.threshold >= 0) curve.from = std::max(lo, r.value[model.threshold] + 1e-6 * (hi - lo));
    spec.curves.push_back(curve);
    if (with_classical) {
      const auto& classical = find_model("kc-classical");
      FitOptions ko;
      ko.loss = ml ? Loss::Linear : report.loss;
      figure.classical = fit(classical, d.x, d.y, ko);
      const auto& kc = *figure.classical;
      spec.curves.push_back(
          {&classical, kc.value,
           fmt::format("classical Kozeny-Carman C {{/Symbol f}}^3 / (1 - {{/Symbol f}})^2, R^2 = {:.3f}", kc.r2), lo,
           hi, 1, true});
    }
  }
  return figure;
}

}  // namespace cmp::fit
