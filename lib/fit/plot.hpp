#pragma once
// PNG figure of a fit with gnuplot: the data as points, the fitted curve and, optionally, a
// second curve (the classical Kozeny-Carman law fitted to the same data). gnuplot's pngcairo
// terminal is used when it exists (Debian's gnuplot-nox has it), else the libgd png one.
#include "fit/fit.hpp"

#include <string>
#include <vector>

namespace cmp::fit {

struct PlotCurve {
  const Model* model = nullptr;
  std::vector<double> p;  // parameters
  std::string title;
};

struct PlotSpec {
  std::string x_label, y_label, title;
  bool log_y = false;                 // logarithmic y axis (log loss)
  std::vector<double> x, y;           // data
  std::vector<PlotCurve> curves;      // first: the fit
  double curve_from = 0, curve_to = 1;  // x range of the curves
};

// Renders spec into a temporary PNG beside path and returns its name; commit_plot() renames
// it onto path, discard_plot() removes it. Throws cmp::ComputationError when gnuplot is
// missing or fails, cmp::InputError(path, 0, ...) when the folder is not writable.
std::string render_plot(const std::string& path, const PlotSpec& spec);
void commit_plot(const std::string& temp, const std::string& path);
void discard_plot(const std::string& temp);

// "pngcairo" or "png", whichever the installed gnuplot offers (asked once); throws
// cmp::ComputationError when there is no gnuplot.
std::string png_terminal();

}  // namespace cmp::fit
