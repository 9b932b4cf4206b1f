#pragma once
// lbflow's output table (docs/formats.md): one row per input, columns named as percolate and
// kcfit name them (porosity, permeability_delta2 / permeability_d02, tortuosity), so that
// `kcfit flows.csv --model kc-percolation` and `--model tortuosity` read it as it is.
#include "flowrun/flow_case.hpp"
#include "lbm/flow_solver.hpp"
#include "lbm/steady_state.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cmp::io {
class CsvWriter;
}

namespace cmp::flowrun {

// What a run gives besides the case itself.
struct FlowOutcome {
  lbm::SteadyStateResult result;
  long fluid_nodes = 0;
  double bytes_per_fluid_node = 0;
  long interpolated_links = 0;
  long steps_run = 0;        // steps of this process (a resumed run: since the resume)
  double seconds = 0;        // wall time of the steps of this process
  double halo_bytes_per_step = 0;  // sent between ranks per step, all ranks together
  double halo_seconds = 0;   // rank 0's wall time in the halo exchange
};

// Column names, in order; `timings` adds seconds, mlups, halo_bytes_per_step and halo_seconds
// (never written otherwise, so the same input gives the same numbers).
std::vector<std::string> flow_columns(bool timings);

// The row of one run, formatted (numbers round-trip; unknown units such as D0 for an image
// without field data are empty cells).
std::vector<std::string> flow_row(const FlowCase& c, const lbm::FlowSettings& settings, const FlowOutcome& outcome,
                                  bool timings);

// The one-line summary of a run for stderr (without the "lbflow: " prefix): kappa in lattice
// units, delta^2 and D0^2, tau_H, porosity, nodes, steps, Re, Ma, dropped pockets; the wall
// time and MLUPS with timings.
std::string flow_summary(const FlowCase& c, const FlowOutcome& outcome, bool timings);

// The "# key=value" lines of the table: provenance, the solver settings, the convergence
// rule, and what the columns mean (units).
void write_flow_meta(io::CsvWriter& csv, const std::string& provenance, const lbm::FlowSettings& settings,
                     const lbm::ConvergenceSettings& convergence);

// --history: one row per convergence check of every input (file, steps, permeability_lu,
// permeability_delta2, tortuosity, kappa_change, tortuosity_change, mach, mass), the
// change relative to the check `window` checks earlier (empty before there is one).
std::vector<std::string> history_columns();
std::vector<std::vector<std::string>> history_rows(const FlowCase& c, const lbm::SteadyStateResult& result,
                                                   long window);

// The relative change of kappa and of tau_H between check k and check k - window (the larger
// of the two: what must fall below --tol); nullopt for k < window.
std::optional<double> relative_change(const std::vector<lbm::FlowObservables>& history, std::size_t k, long window);

}  // namespace cmp::flowrun
