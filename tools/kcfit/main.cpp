// kcfit: non-linear fits of the Kozeny-Carman, percolation and threshold laws of thesis
// Chapter 5 (5.5.6, Table S5.1) to the CSV tables of percolate and lbflow.
//   kcfit flow.csv --model kc-percolation --loss log --plot kc.png > fit.csv
//   kcfit perc.csv --model threshold --x delta --y phi_c
//   kcfit --list-models
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "fit/bootstrap.hpp"
#include "fit/fit.hpp"
#include "fit/plot.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <sstream>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::string input, output = "-", model, x, y, loss = "auto", plot;
  std::vector<std::string> fix, free;
  bool plot_kc = false, list = false;
  int bootstrap = 0, max_iterations = 500;
};

// "--fix a=1,b=2" (the option may be repeated) as (name, value) pairs.
std::vector<std::pair<std::string, double>> parse_fix(const std::vector<std::string>& args) {
  std::vector<std::pair<std::string, double>> fixed;
  for (const auto& arg : args) {
    std::stringstream items(arg);
    std::string item;
    while (std::getline(items, item, ',')) {
      const auto eq = item.find('=');
      double value = 0;
      if (eq == std::string::npos || eq == 0 || !io::try_parse_double(item.substr(eq + 1), value))
        throw UsageError("--fix: expected name=value[,name=value], e.g. --fix phi_c=0.141; got '" + item + "'");
      fixed.emplace_back(item.substr(0, eq), value);
    }
  }
  if (args.size() && fixed.empty()) throw UsageError("--fix: expected name=value[,name=value]");
  return fixed;
}

void list_models() {
  for (const auto& m : fit::models()) {
    std::cout << m.name << ": " << m.formula << "\n    " << m.source << "\n    domain " << m.domain
              << "; default columns --x " << m.x_column << " --y " << m.y_column << "\n";
    for (const auto& p : m.params)
      std::cout << fmt::format("    {:<11} {}{}\n", p.name, p.meaning,
                               p.fixed_by_default ? fmt::format(" (fixed at {} unless --free {})", p.start, p.name) : "");
  }
}

std::string pm(const fit::FitResult& r, std::size_t k) {
  return r.fixed[k] ? fmt::format("{} = {:.4g} (fixed)", r.names[k], r.value[k])
                    : fmt::format("{} = {:.4g} ± {:.2g}", r.names[k], r.value[k], r.error[k]);
}

int run(const Options& o, const std::string& provenance) {
  const auto& model = fit::find_model(o.model);
  const auto table = io::read_csv(o.input);
  const std::string xname = o.x.empty() ? model.x_column : o.x, yname = o.y.empty() ? model.y_column : o.y;
  const int xc = table.column(xname), yc = table.column(yname);
  if (table.rows.empty()) throw InputError(o.input, table.header_line, "no data rows below the header");
  std::vector<double> x, y;
  for (std::size_t i = 0; i < table.rows.size(); ++i) x.push_back(table.number(i, xc)), y.push_back(table.number(i, yc));

  fit::FitOptions fo;
  fo.fixed = parse_fix(o.fix);
  fo.freed = o.free;
  fo.max_iterations = o.max_iterations;
  const bool binary = std::all_of(y.begin(), y.end(), [](double v) { return v == 0 || v == 1; });
  fo.loss = o.loss == "auto" ? (model.probability && binary ? fit::Loss::MaxLikelihood : fit::Loss::Linear)
                             : fit::parse_loss(o.loss);
  if (fo.loss == fit::Loss::MaxLikelihood && !model.probability)
    throw UsageError(fmt::format("--loss ml is for 0/1 outcomes and the sigmoid model, not {}", model.name));
  if (fo.loss == fit::Loss::MaxLikelihood)
    for (std::size_t i = 0; i < y.size(); ++i)
      if (y[i] != 0 && y[i] != 1)
        throw InputError(o.input, table.row_lines[i], fmt::format("--loss ml needs {} to be 0 or 1, got {}", yname, y[i]));

  const auto r = fit::fit(model, x, y, fo);
  fit::BootstrapResult boot;
  if (o.bootstrap > 0) boot = fit::bootstrap(model, x, y, fo, r, o.bootstrap, o.common.seed);

  // The plot first (into a hidden file), so that a gnuplot failure leaves no output at all.
  std::string plot_temp;
  fit::FitResult kc;
  if (!o.plot.empty()) {
    fit::PlotSpec spec;
    spec.x_label = xname, spec.y_label = yname, spec.x = x, spec.y = y;
    spec.log_y = fo.loss == fit::Loss::Log;
    spec.title = fmt::format("{}: {} ({} loss, R^2 = {:.4f})", model.name, model.formula, fit::loss_name(fo.loss), r.r2);
    std::string label;
    for (std::size_t k = 0; k < r.names.size(); ++k) label += (k ? ", " : "") + pm(r, k);
    spec.curves.push_back({&model, r.value, "fit: " + label});
    const double lo = *std::min_element(x.begin(), x.end()), hi = *std::max_element(x.begin(), x.end());
    spec.curve_from = model.name == "threshold" ? 0.0 : lo;
    spec.curve_to = hi;
    if (model.threshold >= 0) spec.curve_from = std::max(lo, r.value[model.threshold] + 1e-6 * (hi - lo));
    if (o.plot_kc) {
      const auto& classical = fit::find_model("kc-classical");
      fit::FitOptions ko;
      ko.loss = fo.loss == fit::Loss::MaxLikelihood ? fit::Loss::Linear : fo.loss;
      kc = fit::fit(classical, x, y, ko);
      spec.curves.push_back({&classical, kc.value, fmt::format("classical KC: C x^3/(1-x)^2, R^2 = {:.4f}", kc.r2)});
    }
    plot_temp = fit::render_plot(o.plot, spec);
  }
  try {
    io::AtomicOutput out(o.output);
    io::CsvWriter csv(out.stream());
    for (const auto& [key, value] : table.meta) csv.meta("input." + key, value);
    csv.meta("provenance", provenance);
    const std::vector<std::pair<std::string, std::string>> meta{
        {"input", o.input}, {"model", model.name}, {"formula", model.formula}, {"loss", fit::loss_name(fo.loss)},
        {"x", xname}, {"y", yname}, {"n", std::to_string(r.n)}, {"dropped", std::to_string(r.dropped)},
        {"rss", io::format_number(r.rss)}, {"r2", io::format_number(r.r2)}, {"aic", io::format_number(r.aic)},
        {"status", r.status}, {"iterations", std::to_string(r.iterations)},
        {"starts", fmt::format("{} converged of {}", r.starts_converged, r.starts)},
        {"at_bound", r.at_bound ? "1" : "0"}};
    for (const auto& [key, value] : meta) csv.meta(key, value);
    if (r.dropped) csv.meta("dropped_why", r.dropped_why);
    if (fo.loss == fit::Loss::MaxLikelihood) csv.meta("log_likelihood", io::format_number(r.log_likelihood));
    if (o.plot_kc && !o.plot.empty()) csv.meta("kc_classical_C", io::format_number(kc.value[0]));
    if (o.bootstrap > 0) {
      csv.meta("bootstrap", std::to_string(boot.replicas));
      csv.meta("bootstrap_seed", std::to_string(o.common.seed));
      csv.meta("bootstrap_failed", std::to_string(boot.failed));
    }
    std::vector<std::string> header{"parameter", "value", "stderr", "fixed"};
    for (const auto& n : r.names) header.push_back("cov_" + n);
    if (o.bootstrap > 0)
      for (const char* h : {"bootstrap_mean", "bootstrap_stderr", "bootstrap_q025", "bootstrap_q975"}) header.push_back(h);
    csv.header(header);
    for (std::size_t k = 0; k < r.names.size(); ++k) {
      std::vector<std::string> row{r.names[k], io::format_number(r.value[k]), io::format_number(r.error[k]),
                                   r.fixed[k] ? "1" : "0"};
      for (std::size_t j = 0; j < r.names.size(); ++j) row.push_back(io::format_number(r.covariance(k, j)));
      if (o.bootstrap > 0)
        for (double v : {boot.mean[k], boot.stddev[k], boot.q025[k], boot.q975[k]}) row.push_back(io::format_number(v));
      csv.row(row);
    }
    out.commit();
  } catch (...) {
    if (!plot_temp.empty()) fit::discard_plot(plot_temp);
    throw;
  }
  if (!plot_temp.empty()) fit::commit_plot(plot_temp, o.plot);
  if (!o.common.quiet) {
    std::string line;
    for (std::size_t k = 0; k < r.names.size(); ++k) line += (k ? ", " : "") + pm(r, k);
    std::cerr << fmt::format("kcfit: {} ({} loss), {} points{}: {}; R^2 = {:.4f}, AIC = {:.4g}; {}{}\n", model.name,
                             fit::loss_name(fo.loss), r.n, r.dropped ? fmt::format(" ({} dropped: {})", r.dropped, r.dropped_why) : "",
                             line, r.r2, r.aic, r.status, r.at_bound ? "; WARNING: a parameter ended on its bound" : "");
    if (r.n == r.free_parameters)
      std::cerr << "kcfit: warning: as many points as free parameters: the standard errors are undefined (inf)\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("kcfit", [&] {
    Options o;
    auto app = cli::make_app("kcfit", "Non-linear fits of the Kozeny-Carman, percolation and threshold laws "
                                      "(thesis 5.5.6, Table S5.1) to CSV tables.");
    app->add_option("input", o.input, "CSV table with a header row ('-': stdin)");
    app->add_flag("--list-models", o.list, "print the models, their formulas and parameters, then exit");
    app->add_option("-m,--model", o.model, "model to fit (--list-models)");
    app->add_option("--x", o.x, "column of the abscissa (default: the model's, e.g. porosity)");
    app->add_option("--y", o.y, "column of the ordinate (default: the model's, e.g. permeability)");
    app->add_option("--loss", o.loss,
                    "linear: sum (f - y)^2; log: sum (ln f - ln y)^2; ml: maximum likelihood for 0/1 outcomes "
                    "(sigmoid); auto: ml for the sigmoid on 0/1 data, else linear");
    app->add_option("--fix", o.fix, "hold parameters at values: name=value[,name=value] (repeatable)")
        ->allow_extra_args(false);
    app->add_option("--free", o.free, "fit a parameter that is fixed by default (the tortuosity exponent e)")
        ->allow_extra_args(false);
    app->add_option("--max-iter", o.max_iterations, "solver iterations per starting point")->check(CLI::Range(1, 1000000));
    app->add_option("--plot", o.plot, "also draw data and fit into this PNG (gnuplot)");
    app->add_flag("--plot-kc", o.plot_kc, "add the classical Kozeny-Carman law C x^3/(1-x)^2, fitted too, to the plot");
    app->add_option("--bootstrap", o.bootstrap, "also estimate errors from N bootstrap resamples")->check(CLI::Range(0, 10000000));
    cli::add_seed_option(*app, o.common);
    cli::add_threads_option(*app, o.common);
    app->add_option("-o,--output", o.output, "output CSV: parameters, errors, covariance ('-': stdout)");
    cli::add_quiet_option(*app, o.common);
    cli::parse(*app, argc, argv);
    if (o.list) {
      list_models();
      return 0;
    }
    cli::OptionChecks checks;
    checks.require(!o.input.empty(), "an input CSV file is required (or --list-models)");
    checks.require(!o.model.empty(), "--model is required (kcfit --list-models)");
    checks.require(!o.plot_kc || !o.plot.empty(), "--plot-kc needs --plot");
    checks.throw_if_any();
    cli::apply_threads(o.common);
    return run(o, cli::provenance("kcfit", argc, argv));
  });
}
