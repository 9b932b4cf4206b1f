// kcfit: non-linear fits of the Kozeny-Carman, percolation and threshold laws of thesis
// Chapter 5 (5.5.6, Table S5.1) to the CSV tables of percolate and lbflow.
//   kcfit flow.csv --model kc-percolation --loss log --plot kc.png > fit.csv
//   kcfit perc.csv --model sigmoid --group-by delta -o phi_c.csv && kcfit phi_c.csv --model threshold
//   kcfit --list-models
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "fit/fit.hpp"
#include "fit/fit_figure.hpp"
#include "fit/fit_inputs.hpp"
#include "fit/fit_report.hpp"
#include "fit/fix_option.hpp"
#include "fit/group_fit.hpp"
#include "fit/model_list.hpp"
#include "fit/plot.hpp"
#include "fit/selection.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::vector<std::string> inputs, fix, free, where, group_by;
  std::string output = "-", model, x, y, sigma, loss = "auto", plot, xlabel, ylabel;
  bool plot_kc = false, list = false;
  int bootstrap = 0, max_iterations = 500;
};

int run(const Options& o, const fit::Model& model, const fit::FitOptions& base, const std::vector<fit::Condition>& where,
        fit::PlotFormat plot_format, const std::string& provenance) {
  std::vector<io::CsvTable> tables;
  for (const auto& in : o.inputs) tables.push_back(io::read_csv(in));
  const fit::Rows rows = fit::merge_tables(tables);
  if (rows.cells.empty()) throw InputError(rows.files[0], rows.header_line, "no data rows below the header");
  const int xc = fit::resolve_column(rows, o.x, model.x_columns, "--x", model.name);
  const int yc = fit::resolve_column(rows, o.y, model.y_columns, "--y", model.name);
  const std::string xname = rows.header[xc], yname = rows.header[yc];
  std::vector<int> gc;
  for (const auto& g : o.group_by) gc.push_back(rows.column(g, "--group-by"));
  const auto selected = fit::select_rows(rows, where);
  if (selected.empty())
    throw InputError(rows.files[0], rows.header_line,
                     fmt::format("no row satisfies --where {}", fmt::join(o.where, " --where ")));
  // The loss: maximum likelihood for the sigmoid on 0/1 outcomes unless told otherwise.
  fit::FitOptions fo = base;
  fit::check_outcomes(model, rows, selected, yc);
  fo.loss = fit::choose_loss(o.loss, model, rows, selected, yc);
  const int sc = fit::sigma_column(rows, o.sigma, fo.loss, yname);

  fit::FitReport report;
  std::vector<fit::GroupData> data;
  for (const auto& g : fit::group_rows(rows, selected, gc)) {
    data.push_back(fit::group_data(rows, g.rows, xc, yc, sc, fo.loss));
    report.fits.push_back(fit::fit_group(model, data.back(), fo, o.bootstrap, o.common.seed, o.group_by, g.key));
    report.sigma_zero += data.back().sigma_zero;
  }
  report.input_meta = rows.meta;
  report.provenance = provenance;
  report.inputs = o.inputs;
  report.model = &model;
  report.loss = fo.loss;
  report.x = xname, report.y = yname;
  if (sc >= 0) report.sigma = rows.header[sc];
  report.where = o.where;
  report.group_by = o.group_by;
  report.bootstrap = o.bootstrap, report.seed = o.common.seed;

  // Different voxel sides or particle numbers are different systems (the scale is not: it is
  // what moves the porosity of one packing).
  if (o.group_by.empty() && o.where.empty() && !o.common.quiet)
    for (const auto& w : fit::mixed_systems(rows, selected, xc, yc)) std::cerr << "kcfit: warning: " << w << "\n";
  // The figure first (in memory), so that a gnuplot failure leaves no output at all.
  std::string figure;
  if (!o.plot.empty()) {
    const auto f = fit::fit_figure(report, data, o.xlabel, o.ylabel, o.plot_kc);
    if (f.classical) report.kc_classical = f.classical->value[0];
    figure = fit::render_plot(plot_format, f.spec);
  }
  io::AtomicOutput out(o.output);
  io::CsvWriter csv(out.stream());
  csv.allow_infinity();  // undefined standard errors are inf, as curve_fit reports them
  fit::write_report_csv(csv, report);
  std::unique_ptr<io::AtomicOutput> plot;
  if (!o.plot.empty()) {
    plot = std::make_unique<io::AtomicOutput>(o.plot);
    plot->stream().write(figure.data(), static_cast<std::streamsize>(figure.size()));
  }
  io::commit_in_order({&out, plot.get()});
  if (!o.common.quiet) std::cerr << fit::report_summary("kcfit", report);
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
    tool.declare_inputs(*app, o.inputs);
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
    tool.add_output(*app, "--plot", o.plot, "also draw data and fit with gnuplot into this .png, .svg or .pdf file");
    app->add_option("--xlabel", o.xlabel,
                    "x axis label of the plot, gnuplot enhanced text (default from the column: porosity -> "
                    "'porosity {/Symbol f}', delta -> 'voxel side {/Symbol d} / D_0', ...)");
    app->add_option("--ylabel", o.ylabel, "y axis label of the plot (default from the column)");
    app->add_flag("--plot-kc", o.plot_kc, "add the classical Kozeny-Carman law C x^3/(1-x)^2, fitted too, to the plot");
    tool.add_int(*app, "--bootstrap", o.bootstrap, "also estimate errors from N bootstrap resamples",
                 cli::closed(0, 10000000));
    tool.add_common(*app, o.common, cli::Tool::kSeed | cli::Tool::kThreads);
    tool.add_output(*app, "-o,--output", o.output, "output CSV: one row per parameter (value, error, covariance), or with --group-by one row per group "
                  "(group columns, then <p>,<p>_error ...); '-': stdout");
    tool.add_common(*app, o.common, cli::Tool::kQuiet);
    tool.parse(argc, argv);
    if (o.list) {
      tool.finish_checks();  // a bad number given with it
      fit::write_model_list(std::cout);
      return 0;
    }
    tool.check(!o.inputs.empty(), "", "an input CSV file is required (or --list-models)");
    tool.check(!o.model.empty(), "--model", "required (kcfit --list-models lists the models)");
    const fit::Model* model = nullptr;
    if (!o.model.empty()) tool.collect("--model", [&] { model = &fit::find_model(o.model); });
    fit::FitOptions fo;
    std::vector<std::string> bad_fix;
    fo.fixed = fit::parse_fix(o.fix, bad_fix);
    for (const auto& message : bad_fix) tool.check(false, "--fix", message);
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
