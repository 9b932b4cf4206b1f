// kcfit: non-linear fits of the Kozeny-Carman, percolation and threshold laws of thesis
// Chapter 5 (5.5.6, Table S5.1) to the CSV tables of percolate and lbflow.
//   kcfit flow.csv --model kc-percolation --loss log --plot kc.png > fit.csv
//   kcfit perc.csv --model sigmoid --group-by delta -o phi_c.csv && kcfit phi_c.csv --model threshold
//   kcfit --list-models
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "fit/bootstrap.hpp"
#include "fit/fit.hpp"
#include "fit/fit_table.hpp"
#include "fit/plot.hpp"
#include "fit/selection.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::vector<std::string> inputs, fix, free, where, group_by;
  std::string output = "-", model, x, y, sigma, loss = "auto", plot, xlabel, ylabel;
  bool plot_kc = false, list = false;
  int bootstrap = 0, max_iterations = 500;
};

// "--fix a=1,b=2" (the option may be repeated) as (name, value) pairs; problems into tool.
std::vector<std::pair<std::string, double>> parse_fix(const std::vector<std::string>& args, cli::Tool& tool) {
  std::vector<std::pair<std::string, double>> fixed;
  for (const auto& arg : args) {
    std::stringstream items(arg);
    std::string item;
    while (std::getline(items, item, ',')) {
      const auto eq = item.find('=');
      double value = 0;
      if (eq == std::string::npos || eq == 0)
        tool.check(false, "--fix", "expected name=value[,name=value], e.g. --fix phi_c=0.141; got '" + item + "'");
      else if (!io::try_parse_double(item.substr(eq + 1), value))
        tool.check(false, "--fix", fmt::format("'{}' is not a finite number (in {})", item.substr(eq + 1), item));
      else
        fixed.emplace_back(item.substr(0, eq), value);
    }
  }
  return fixed;
}

std::string joined(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : sep) + e;
  return s;
}

void list_models() {
  for (const auto& m : fit::models()) {
    std::cout << m.name << ": " << m.formula << "\n    " << m.source << "\n    domain " << m.domain
              << "; default columns --x " << joined(m.x_columns, " or ") << " --y " << joined(m.y_columns, " or ")
              << " (the first present)\n";
    for (const auto& p : m.params)
      std::cout << fmt::format("    {:<11} {}{}\n", p.name, p.meaning,
                               p.fixed_by_default ? fmt::format(" (fixed at {} unless --free {})", p.start, p.name) : "");
  }
  std::cout << "columns (as percolate, percolate sweep, lbflow and kcfit write them):\n"
               "    porosity             geometric porosity of a packing (percolate)\n"
               "    percolates           0/1: the void percolates along the flow axis (percolate, one row per run)\n"
               "    probability          fraction percolating per porosity bin, probability_error its binomial\n"
               "                         standard error (percolate sweep)\n"
               "    delta                voxel side in D_0\n"
               "    phi_c, phi_c_error   threshold per group (kcfit --model sigmoid --group-by delta)\n"
               "    permeability_delta2  permeability in units of delta^2 (lbflow's lattice units);\n"
               "                         permeability_d02 in D_0^2\n"
               "    rh_sites_d0          hydraulic radius in D_0 (percolate)\n"
               "    tortuosity           hydraulic tortuosity tau_H (lbflow)\n"
               "    <y>_error            standard error of y: weights the linear loss (--sigma)\n";
}

// The column given by the option, else the model's first default present.
int resolve_column(const fit::Rows& rows, const std::string& given, const std::vector<std::string>& defaults,
                   const std::string& flag, const std::string& model) {
  if (!given.empty()) return rows.column(given, flag);
  for (const auto& d : defaults)
    if (rows.find(d) >= 0) return rows.find(d);
  std::vector<std::string> others(defaults.begin() + 1, defaults.end());
  return rows.column(defaults.front(), fmt::format("{}the default {} of model {}; name one with {}",
                                                   others.empty() ? "" : "nor '" + joined(others, "', '") + "': ",
                                                   flag, model, flag));
}

// "name = value ± error", the value to the error's second significant digit.
std::string pm(const fit::FitResult& r, std::size_t k, bool enhanced) {
  const std::string name = enhanced ? fit::symbol(r.names[k]) : r.names[k];
  if (r.fixed[k]) return fmt::format("{} = {:.4g} (fixed)", name, r.value[k]);
  const double e = r.error[k];
  if (!(e > 0) || !std::isfinite(e)) return fmt::format("{} = {:.4g} ± {:.2g}", name, r.value[k], e);
  const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(e))), 0, 12);
  return fmt::format("{} = {:.{}f} ± {:.{}f}", name, r.value[k], decimals, e, decimals);
}
std::string parameters(const fit::FitResult& r, bool enhanced) {
  std::string s;
  for (std::size_t k = 0; k < r.names.size(); ++k) s += (k ? ", " : "") + pm(r, k, enhanced);
  return s;
}
// The fit's own goodness measure, for the summary (enhanced: for a figure).
std::string quality(const fit::FitResult& r, bool enhanced) {
  if (r.loss == fit::Loss::MaxLikelihood)
    return fmt::format("ln L = {:.4g}, deviance = {:.4g}, McFadden pseudo-R{} = {:.3f}", r.log_likelihood, r.deviance,
                       enhanced ? "^2" : "^2", r.pseudo_r2);
  return fmt::format("R^2{} = {:.4f}, {}/dof = {:.3g}", r.loss == fit::Loss::Log ? " (ln y)" : "", r.r2,
                     enhanced ? "{/Symbol c}^2" : "chi^2", r.chi2_dof);
}

struct Data {
  std::vector<double> x, y, sigma;
  long sigma_zero = 0;
};

int run(const Options& o, const fit::Model& model, const fit::FitOptions& base, const std::vector<fit::Condition>& where,
        fit::PlotFormat plot_format, const std::string& provenance) {
  std::vector<io::CsvTable> tables;
  for (const auto& in : o.inputs) tables.push_back(io::read_csv(in));
  const fit::Rows rows = fit::merge_tables(tables);
  if (rows.cells.empty()) throw InputError(rows.files[0], rows.header_line, "no data rows below the header");
  const int xc = resolve_column(rows, o.x, model.x_columns, "--x", model.name);
  const int yc = resolve_column(rows, o.y, model.y_columns, "--y", model.name);
  const std::string xname = rows.header[xc], yname = rows.header[yc];
  std::vector<int> gc;
  for (const auto& g : o.group_by) gc.push_back(rows.column(g, "--group-by"));
  const auto selected = fit::select_rows(rows, where);
  if (selected.empty())
    throw InputError(rows.files[0], rows.header_line, "no row satisfies --where " + joined(o.where, " --where "));
  // The loss: maximum likelihood for the sigmoid on 0/1 outcomes unless told otherwise.
  fit::FitOptions fo = base;
  bool binary = true;
  for (std::size_t i : selected) binary = binary && (rows.number(i, yc) == 0 || rows.number(i, yc) == 1);
  fo.loss = o.loss == "auto" ? (model.probability && binary ? fit::Loss::MaxLikelihood : fit::Loss::Linear)
                             : fit::parse_loss(o.loss);
  int sc = -1;
  if (!o.sigma.empty() && o.sigma != "none") sc = rows.column(o.sigma, "--sigma");
  else if (o.sigma.empty() && fo.loss == fit::Loss::Linear) sc = rows.find(yname + "_error");

  const auto groups = fit::group_rows(rows, selected, gc);
  std::vector<fit::GroupFit> fits;
  std::vector<Data> data;
  for (const auto& g : groups) {
    Data d;
    for (std::size_t i : g.rows) {
      d.x.push_back(rows.number(i, xc)), d.y.push_back(rows.number(i, yc));
      if (fo.loss == fit::Loss::MaxLikelihood && d.y.back() != 0 && d.y.back() != 1)
        throw InputError(rows.files[rows.source[i]], rows.lines[i],
                         fmt::format("--loss ml needs {} to be 0 or 1, got {}", yname, d.y.back()));
      if (sc < 0) continue;
      d.sigma.push_back(rows.number(i, sc));
      if (d.sigma.back() < 0)
        throw InputError(rows.files[rows.source[i]], rows.lines[i],
                         fmt::format("{} (the standard error of {}) is negative: {}", rows.header[sc], yname, d.sigma.back()));
    }
    // A zero error (a bin where every packing percolates, or none) would weigh its point
    // infinitely: it takes the smallest positive error of the group instead.
    double smallest = fit::kInf;
    for (double s : d.sigma)
      if (s > 0) smallest = std::min(smallest, s);
    for (double& s : d.sigma)
      if (s == 0) s = smallest, ++d.sigma_zero;
    fit::GroupFit gf;
    for (double k : g.key) gf.key.push_back(io::format_number(k));
    std::string where_text;
    for (std::size_t k = 0; k < gc.size(); ++k) where_text += fmt::format("{}{}={}", k ? "," : "", o.group_by[k], gf.key[k]);
    try {
      if (!d.sigma.empty() && !std::isfinite(smallest))
        throw ComputationError(fmt::format("every {} is 0: no weights (--sigma none fits unweighted)", rows.header[sc]));
      gf.result = fit::fit(model, d.x, d.y, fo, d.sigma);
      if (o.bootstrap > 0) gf.boot = fit::bootstrap(model, d.x, d.y, fo, gf.result, o.bootstrap, o.common.seed, d.sigma);
    } catch (const ComputationError& e) {
      if (gc.empty()) throw;
      throw ComputationError(where_text + ": " + e.what());
    }
    fits.push_back(std::move(gf));
    data.push_back(std::move(d));
  }

  // Different voxel sides or particle numbers are different systems (the scale is not: it is
  // what moves the porosity of one packing).
  if (o.group_by.empty() && o.where.empty() && !o.common.quiet)
    for (const char* c : {"delta", "particles"}) {
      const int k = rows.find(c);
      if (k < 0 || k == xc || k == yc) continue;
      const auto v = fit::distinct_values(rows, selected, k);
      if (v.size() > 1)
        std::cerr << fmt::format("kcfit: warning: the data hold {} values of {} ({} ... {}), fitted as one set; "
                                 "fit each with --group-by {} or --where {}=VALUE\n",
                                 v.size(), c, io::format_number(v.front()), io::format_number(v.back()), c, c);
    }
  // The figure first (in memory), so that a gnuplot failure leaves no output at all.
  std::string figure;
  fit::FitResult kc;
  if (!o.plot.empty()) {
    fit::PlotSpec spec;
    spec.x_label = o.xlabel.empty() ? fit::axis_label(xname) : o.xlabel;
    spec.y_label = o.ylabel.empty() ? fit::axis_label(yname) : o.ylabel;
    spec.log_y = fo.loss == fit::Loss::Log;
    spec.probability = model.probability;
    const bool ml = fo.loss == fit::Loss::MaxLikelihood;
    std::string how = ml ? "maximum likelihood on 0/1 outcomes" : fmt::format("least squares ({} loss{})", fit::loss_name(fo.loss), sc >= 0 ? ", weighted by " + rows.header[sc] : "");
    std::vector<std::string> group_symbols;
    for (const auto& g : o.group_by) group_symbols.push_back(fit::symbol(g));
    spec.title = model.title + "\n{/*0.8 " + fit::enhanced_literal(how) +
                 (gc.empty() ? fmt::format(", n = {}: {}", fits[0].result.n, quality(fits[0].result, true)) : ", one fit per " + joined(group_symbols, " and ")) + "}";
    for (std::size_t g = 0; g < fits.size(); ++g) {
      const auto& r = fits[g].result;
      const auto& d = data[g];
      std::string label;
      for (std::size_t k = 0; k < gc.size(); ++k)
        label += fmt::format("{}{} = {}", k ? ", " : "", fit::symbol(o.group_by[k]), fits[g].key[k]);
      fit::PlotPoints pts;
      if (ml) {
        const int bins = std::clamp(static_cast<int>(std::lround(std::sqrt(d.x.size() / 2.0))), 4, 20);
        pts = fit::binned_outcomes(d.x, d.y, bins);
        pts.title = gc.empty() ? fmt::format("fraction per bin of {} (68 % binomial interval)", bins) : "";
      } else {
        pts.x = d.x, pts.y = d.y;
        for (std::size_t i = 0; i < d.sigma.size(); ++i) pts.low.push_back(d.y[i] - d.sigma[i]), pts.high.push_back(d.y[i] + d.sigma[i]);
        pts.title = gc.empty() ? "data" : "";
      }
      spec.points.push_back(pts);
      fit::PlotCurve curve{&model, r.value, "", 0, 1, static_cast<int>(g), false};
      curve.title = gc.empty() ? "fit: " + parameters(r, true)
                               : label + ": " + parameters(r, true) + (ml ? fmt::format(", pseudo-R^2 = {:.2f}", r.pseudo_r2) : "");
      const double lo = *std::min_element(d.x.begin(), d.x.end()), hi = *std::max_element(d.x.begin(), d.x.end());
      curve.from = model.name == "threshold" ? 0.0 : lo, curve.to = hi;
      if (model.threshold >= 0) curve.from = std::max(lo, r.value[model.threshold] + 1e-6 * (hi - lo));
      spec.curves.push_back(curve);
      if (o.plot_kc) {
        const auto& classical = fit::find_model("kc-classical");
        fit::FitOptions ko;
        ko.loss = fo.loss == fit::Loss::MaxLikelihood ? fit::Loss::Linear : fo.loss;
        kc = fit::fit(classical, d.x, d.y, ko);
        spec.curves.push_back({&classical, kc.value, fmt::format("classical Kozeny-Carman C {{/Symbol f}}^3 / (1 - {{/Symbol f}})^2, R^2 = {:.3f}", kc.r2),
                               lo, hi, 1, true});
      }
    }
    figure = fit::render_plot(plot_format, spec);
  }
  io::AtomicOutput out(o.output);
  io::CsvWriter csv(out.stream());
  for (const auto& [key, value] : rows.meta) csv.meta("input." + key, value);
  csv.meta("provenance", provenance);
  const std::vector<std::pair<std::string, std::string>> meta{
      {"input", joined(o.inputs, " ")}, {"model", model.name}, {"formula", model.formula}, {"loss", fit::loss_name(fo.loss)},
      {"x", xname}, {"y", yname}};
  for (const auto& [key, value] : meta) csv.meta(key, value);
  if (sc >= 0) csv.meta("sigma", rows.header[sc]);
  long zeros = 0;
  for (const auto& d : data) zeros += d.sigma_zero;
  if (zeros) csv.meta("sigma_zero", fmt::format("{} zero errors replaced by the smallest positive one of their group", zeros));
  if (!where.empty()) csv.meta("where", joined(o.where, " and "));
  if (!gc.empty()) csv.meta("group_by", joined(o.group_by, ","));
  if (o.bootstrap > 0) csv.meta("bootstrap_seed", std::to_string(o.common.seed));
  if (o.plot_kc) csv.meta("kc_classical_C", io::format_number(kc.value[0]));
  if (gc.empty()) fit::write_parameter_table(csv, fits[0].result, &fits[0].boot);
  else fit::write_group_table(csv, o.group_by, fits);
  std::unique_ptr<io::AtomicOutput> plot;
  if (!o.plot.empty()) {
    plot = std::make_unique<io::AtomicOutput>(o.plot);
    plot->stream().write(figure.data(), static_cast<std::streamsize>(figure.size()));
  }
  out.commit();
  if (plot) plot->commit();
  if (o.common.quiet) return 0;
  for (std::size_t g = 0; g < fits.size(); ++g) {
    const auto& r = fits[g].result;
    std::string group;
    for (std::size_t k = 0; k < gc.size(); ++k) group += fmt::format("{}{}={}", k ? "," : "", o.group_by[k], fits[g].key[k]);
    std::cerr << fmt::format("kcfit: {}{} ({} loss{}), {} points{}: {}; {}, AIC = {:.4g}; {}{}\n",
                             group.empty() ? "" : group + ": ", model.name, fit::loss_name(fo.loss),
                             r.weighted ? ", weighted" : "", r.n,
                             r.dropped ? fmt::format(" ({} dropped: {})", r.dropped, r.dropped_why) : "", parameters(r, false),
                             quality(r, false), r.aic, r.status, r.at_bound ? "; WARNING: a parameter ended on its bound" : "");
    if (r.n == r.free_parameters)
      std::cerr << "kcfit: warning: as many points as free parameters: the standard errors are undefined (inf)\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("kcfit", [&] {
    Options o;
    cli::Tool tool("kcfit", "Non-linear fits of the Kozeny-Carman, percolation and threshold laws "
                            "(thesis 5.5.6, Table S5.1) to CSV tables.");
    auto* app = &tool.app();
    app->add_option("inputs", o.inputs, "CSV tables with a header row, the same columns in each ('-': stdin)");
    app->add_flag("--list-models", o.list, "print the models, their formulas, parameters and default columns, then exit");
    app->add_option("-m,--model", o.model, "model to fit (--list-models)");
    app->add_option("--x", o.x, "column of the abscissa (default: the model's, e.g. porosity)");
    app->add_option("--y", o.y, "column of the ordinate (default: the model's, e.g. percolates or probability)");
    app->add_option("--sigma", o.sigma,
                    "column of the standard errors of y, weighting the linear loss by 1/sigma (default: <y>_error when "
                    "there is one, e.g. probability_error; zeros take the group's smallest positive error); none: unweighted");
    app->add_option("--loss", o.loss,
                    "linear: sum (f - y)^2; log: sum (ln f - ln y)^2; ml: maximum likelihood for 0/1 outcomes "
                    "(sigmoid); auto: ml for the sigmoid on 0/1 data, else linear");
    app->add_option("--where", o.where,
                    "keep rows where column=value (also !=, <, <=, >, >=; numbers compared to 1e-9 relative), "
                    "e.g. --where delta=0.04 (repeatable: all must hold)")
        ->allow_extra_args(false);
    app->add_option("--group-by", o.group_by,
                    "one fit per value of these columns, e.g. --group-by delta,particles: one output row per group")
        ->delimiter(',')
        ->allow_extra_args(false);
    app->add_option("--fix", o.fix, "hold parameters at values: name=value[,name=value] (repeatable)")
        ->allow_extra_args(false);
    app->add_option("--free", o.free, "fit a parameter that is fixed by default (the tortuosity exponent e)")
        ->allow_extra_args(false);
    tool.add_int(*app, "--max-iter", o.max_iterations, "solver iterations per starting point", cli::closed(1, 1000000));
    app->add_option("--plot", o.plot, "also draw data and fit with gnuplot into this .png, .svg or .pdf file");
    app->add_option("--xlabel", o.xlabel,
                    "x axis label of the plot, gnuplot enhanced text (default from the column: porosity -> "
                    "'porosity {/Symbol f}', delta -> 'voxel side {/Symbol d} / D_0', ...)");
    app->add_option("--ylabel", o.ylabel, "y axis label of the plot (default from the column)");
    app->add_flag("--plot-kc", o.plot_kc, "add the classical Kozeny-Carman law C x^3/(1-x)^2, fitted too, to the plot");
    tool.add_int(*app, "--bootstrap", o.bootstrap, "also estimate errors from N bootstrap resamples",
                 cli::closed(0, 10000000));
    tool.add_common(*app, o.common, cli::Tool::kSeed | cli::Tool::kThreads);
    app->add_option("-o,--output", o.output, "output CSV: one row per parameter (value, error, covariance), or with --group-by one row per group "
                  "(group columns, then <p>,<p>_error ...); '-': stdout");
    tool.add_common(*app, o.common, cli::Tool::kQuiet);
    tool.parse(argc, argv);
    if (o.list) {
      tool.finish_checks();  // a bad number given with it
      list_models();
      return 0;
    }
    tool.check(!o.inputs.empty(), "", "an input CSV file is required (or --list-models)");
    tool.check(!o.model.empty(), "--model", "required (kcfit --list-models lists the models)");
    const fit::Model* model = nullptr;
    if (!o.model.empty()) tool.collect("--model", [&] { model = &fit::find_model(o.model); });
    fit::FitOptions fo;
    fo.fixed = parse_fix(o.fix, tool);
    fo.freed = o.free;
    fo.max_iterations = o.max_iterations;
    if (o.loss != "auto") tool.collect("--loss", [&] { fit::parse_loss(o.loss); });
    tool.check(o.loss != "ml" || !model || model->probability, "--loss",
               "ml is for 0/1 outcomes and the sigmoid model, not " + o.model);
    tool.check(o.sigma.empty() || o.sigma == "none" || o.loss == "auto" || o.loss == "linear", "--sigma",
               "weights the linear loss only, not --loss " + o.loss);
    std::vector<fit::Condition> where;
    for (const auto& w : o.where) tool.collect("--where", [&] { where.push_back(fit::parse_condition(w)); });
    for (const auto& g : o.group_by) tool.check(!g.empty(), "--group-by", "an empty column name");
    const auto format = fit::plot_format(o.plot);
    tool.check(o.plot.empty() || format.has_value(), "--plot",
               "the figure's format comes from its extension (.png, .svg or .pdf), got '" + o.plot + "'");
    tool.check(!o.plot_kc || !o.plot.empty(), "--plot-kc", "needs --plot");
    tool.check(!o.plot_kc || o.group_by.empty(), "--plot-kc", "draws one fit: not with --group-by");
    tool.finish_checks();
    cli::apply_threads(o.common);
    return run(o, *model, fo, where, format.value_or(fit::PlotFormat::Png), cli::provenance("kcfit", argc, argv));
  });
}
