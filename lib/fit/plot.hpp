#pragma once
// Figures of fits with gnuplot: data points (optionally with error bars), fitted curves, axis
// labels and a title in gnuplot's enhanced text ({/Symbol f} is phi, x_c a subscript). The
// figure's bytes come back from gnuplot's standard output, so the caller writes them through
// io::AtomicOutput like any other output: no temporary exists while gnuplot runs.
#include "fit/fit.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cmp::fit {

// Points of one data set; low/high (empty, or one value per point) draw vertical error bars.
struct PlotPoints {
  std::string title;  // enhanced text; "" for no key entry
  std::vector<double> x, y, low, high;
};

struct PlotCurve {
  const Model* model = nullptr;
  std::vector<double> p;       // parameters
  std::string title;           // enhanced text
  double from = 0, to = 1;     // x range
  int colour = 0;              // index into the palette (the colour of points set `colour`)
  bool dashed = false;
};

struct PlotSpec {
  std::string x_label, y_label, title;  // enhanced text; title may hold "\n"
  bool log_y = false;                   // logarithmic y axis (log loss)
  bool probability = false;             // y axis from -0.05 to 1.05
  std::vector<PlotPoints> points;       // set k is drawn in colour k
  std::vector<PlotCurve> curves;
};

enum class PlotFormat { Png, Svg, Pdf };

// The format named by the file's extension (.png, .svg, .pdf, any case), or nullopt.
std::optional<PlotFormat> plot_format(const std::string& path);

// The figure's bytes (a PNG, SVG or PDF file), drawn by gnuplot: `gnuplot` from PATH, started
// with posix_spawn (no shell; SIGINT and SIGTERM keep their effect on this process), the
// script on its standard input, the figure read from its standard output. PNG uses the
// pngcairo terminal when gnuplot has it, else libgd's png. Throws cmp::ComputationError when
// gnuplot is missing, fails (its messages quoted) or is killed by a signal (named).
std::string render_plot(PlotFormat format, const PlotSpec& spec);

// 0/1 outcomes as the fraction of ones per bin: bins of equal width over [min x, max x]
// (empty bins left out), each point at the mean x of its bin with the 68 % Wilson score
// interval of the binomial fraction as low/high (defined at 0 and 1 too).
PlotPoints binned_outcomes(const std::vector<double>& x, const std::vector<double>& y, int bins);

// The axis label of a CSV column or the symbol of a parameter in enhanced text, with its unit:
// "porosity" -> "porosity {/Symbol f}", "delta" -> "voxel side {/Symbol d} / D_0",
// "phi_c" -> "{/Symbol f}_c" (symbol_only) ...; an unknown name comes back as itself, its
// enhanced-text characters escaped.
std::string axis_label(const std::string& column);
std::string symbol(const std::string& name);
// Text shown literally in enhanced mode (_ ^ @ & ~ { } escaped).
std::string enhanced_literal(const std::string& text);

}  // namespace cmp::fit
