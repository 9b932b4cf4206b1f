#pragma once
// kcfit --plot: the figure of a run's fits (fit_report.hpp's FitReport) as a plot.hpp spec:
// the data of each group (0/1 outcomes binned), its fitted curve with the parameters in the
// key, the loss and goodness in the title, and with --plot-kc the classical Kozeny-Carman law
// fitted to the same points.
#include "fit/fit.hpp"
#include "fit/fit_report.hpp"
#include "fit/group_fit.hpp"
#include "fit/plot.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cmp::fit {

struct FitFigure {
  PlotSpec spec;
  std::optional<FitResult> classical;  // the classical law's fit (with_classical)
};

// The spec of the report's fits, data[g] the points of report.fits[g]. x_label, y_label:
// gnuplot enhanced text, "" for axis_label() of the report's columns. Maximum likelihood
// draws the fraction of ones in clamp(round(sqrt(n / 2)), 4, 20) bins with their 68 %
// interval, least squares the points with their errors as bars. Each curve runs over the
// group's x range (from 0 for the threshold law, from just above the fitted threshold for a
// model with one). with_classical: kc-classical fitted to the points (the linear loss in
// place of ml) and drawn dashed; it throws cmp::ComputationError as fit() does.
FitFigure fit_figure(const FitReport& report, const std::vector<GroupData>& data, const std::string& x_label,
                     const std::string& y_label, bool with_classical);

}  // namespace cmp::fit
