#pragma once
// What kcfit reports of its fits: the output CSV (the run's "# key=value" lines, then
// fit_table.hpp's table: one row per parameter for one fit, one row per group with
// --group-by) and the one-line summary per fit on stderr; and the parameters and goodness of
// a fit as text, for that line and for the figure's key and title (gnuplot enhanced text).
#include "fit/fit.hpp"
#include "fit/fit_table.hpp"
#include "io/csv.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cmp::fit {

// "name = value ± error", the value to the error's second significant digit (4 significant
// digits and "± e" when the error is not positive and finite; "name = value (fixed)"), joined
// by ", ". enhanced: the names as symbols (plot.hpp's symbol(), "{/Symbol f}_c").
std::string parameter_summary(const FitResult& r, bool enhanced);

// The fit's own goodness measure: "ln L = ..., deviance = ..., McFadden pseudo-R^2 = ..." for
// maximum likelihood, "R^2 = ..., chi^2/dof = ..." for least squares ("R^2 (ln y)" for the log
// loss; enhanced: chi as {/Symbol c}).
std::string goodness_summary(const FitResult& r, bool enhanced);

// One run of kcfit: what it read, how it fitted, and the fits (one, or one per group).
struct FitReport {
  std::vector<std::pair<std::string, std::string>> input_meta;  // "# key=value" lines of the first input
  std::string provenance;
  std::vector<std::string> inputs;     // the input files as given
  const Model* model = nullptr;
  Loss loss = Loss::Linear;
  std::string x, y, sigma;             // column names; sigma "": unweighted
  std::vector<std::string> where;      // --where conditions as typed
  std::vector<std::string> group_by;   // group columns; empty: one fit
  int bootstrap = 0;                   // replicas; 0: none
  std::uint64_t seed = 0;              // of the bootstrap
  std::optional<double> kc_classical;  // C of the classical Kozeny-Carman law (--plot-kc)
  long sigma_zero = 0;                 // zero errors replaced, over all groups
  std::vector<GroupFit> fits;          // one per group, in group order; one without group_by
};

// The "# key=value" lines (input.<key> of the input's own, provenance, input, model, formula,
// loss, x, y, and when they apply sigma, sigma_zero, where, group_by, bootstrap_seed,
// kc_classical_C), then write_parameter_table of the one fit or write_group_table of the
// groups.
void write_report_csv(io::CsvWriter& csv, const FitReport& report);

// One line per fit, "<program>: [group: ]model (loss loss[, weighted]), n points[ (k dropped:
// why)]: parameters; goodness, AIC = ...; status[; WARNING: a parameter ended on its bound]".
std::string report_summary(const std::string& program, const FitReport& report);

}  // namespace cmp::fit
