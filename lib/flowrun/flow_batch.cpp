#include "flowrun/flow_batch.hpp"

#include "core/errors.hpp"
#include "flowrun/flow_table.hpp"
#include "flowrun/flow_vtk.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <omp.h>
#include <optional>

namespace cmp::flowrun {

void run_flow_batch(const FlowBatch& o, const std::string& provenance) {
  // Every input is read and checked first: a bad or non-percolating one stops the run
  // before any output is written.
  // On several ranks every rank reads every input (and holds its pore mask); only rank 0
  // writes the outputs and prints.
  const lbm::Communicator& comm = o.run.comm;
  const bool root = comm.root();
  // The decomposition, in the tables' provenance (the results do not depend on it, bit for bit).
  const std::string decomposition = fmt::format(" (ranks={} threads={} per rank)", comm.size(), omp_get_max_threads());
  const std::vector<int> refinements = o.refinements.empty() ? std::vector<int>{o.input.refine} : o.refinements;
  std::vector<RefinementCases> inputs;
  comm.agree([&] {
    if (comm.size() > 1 && std::find(o.inputs.begin(), o.inputs.end(), "-") != o.inputs.end())
      throw UsageError("'-' (standard input) reaches only rank 0 under mpirun: give the input as a file");
    for (const auto& path : o.inputs) inputs.push_back(read_flow_cases(path, o.input, refinements));
  });
  if (root)
    for (const auto& in : inputs)
      for (const auto& skip : in.skipped) std::cerr << "lbflow: " << skip << '\n';
  // The outputs' temporaries appear with their first row, not while the first flow runs.
  std::optional<io::AtomicOutput> csv_out, history_out;
  comm.agree([&] {  // (an output rank 0 cannot open stops every rank with its message)
    if (!root) return;
    csv_out.emplace(o.csv);
    if (!o.history.empty()) history_out.emplace(o.history);
  });
  std::optional<io::CsvWriter> csv, history;
  std::vector<std::string> stalled;
  // A VTK field that cannot be written (a full disk) does not discard the table: said after it.
  std::optional<InputError> vtk_failure;
  CoarseFlow coarse;  // the flow of the refinement before, as the start of the next
  for (std::size_t i = 0; i < inputs.size(); ++i)
  for (std::size_t k = 0; k < inputs[i].cases.size(); ++k) {
    auto& c = inputs[i].cases[k];
    const bool finest = k + 1 == inputs[i].cases.size();
    FlowOutcome out;
    RunPlan plan = o.run;
    if (std::isnan(plan.flow.collision_parameters.tau)) plan.flow.collision_parameters.tau = default_tau(c);
    {
      FlowRun runner(c, plan);
      // With --prolong each refinement after the first starts from the flow of the one before.
      if (o.prolong && k > 0 && o.run.resume.empty()) runner.start_from(prolonged_start(coarse, c.refine, plan.flow));
      out = runner.run();
      if (o.prolong && !finest) coarse = runner.coarse_flow();
      else coarse = {};
      if (finest && !o.vtk_names[i].empty()) try {
          FlowField field = runner.field(out);  // collective: gathered on rank 0
          if (root)
            write_flow_vtk(o.vtk_names[i], field,
                         fmt::format("lbflow flow field of {} M={} (lengths in the input's units, velocity and "
                                     "density in lattice units) | {}", c.file, c.refine, provenance));
        } catch (const InputError& e) {
          if (!vtk_failure) vtk_failure = e;
        }
    }
    c.release_lattice();
    if (!root) continue;
    if (!csv) {
      csv.emplace(csv_out->stream());
      write_flow_meta(*csv, provenance + decomposition, plan.flow, o.run.convergence);
      csv->header(flow_columns(o.timings));
    }
    csv->row(flow_row(c, plan.flow, out, o.timings));
    if (history_out) {
      if (!history) {
        history.emplace(history_out->stream());
        history->meta("provenance", provenance + decomposition);
        history->meta("change", "max of the relative changes of kappa and tau_H over the last --window checks");
        history->header(history_columns());
      }
      for (const auto& row : history_rows(c, out.result, o.run.convergence.window)) history->row(row);
    }
    if (!o.quiet || o.timings) std::cerr << "lbflow: " << flow_summary(c, out, o.timings) << '\n';
    const auto& r = out.result.final;
    if (r.mach > 0.1 || r.reynolds > 1)
      std::cerr << fmt::format("lbflow: warning: {}: Mach number {:.3g} (max |u| / c_s), Reynolds number {:.3g}: the "
                               "flow leaves the Stokes regime (keep Ma below 0.1 and Re below 1): lower --{}\n",
                               c.file, r.mach, r.reynolds, o.drop_option);
    if (!out.result.converged) {
      const auto& h = out.result.history;
      const auto change = h.empty() ? std::nullopt : relative_change(h, h.size() - 1, o.run.convergence.window);
      stalled.push_back(fmt::format("{}: not converged after {} steps (--max-steps): kappa {:.6g} lu, relative change "
                                    "{} over the last {} checks, --tol {}{}",
                                    c.file, r.steps, r.kappa_lu, change ? fmt::format("{:.3g}", *change) : "unknown",
                                    o.run.convergence.window, io::format_number(o.run.convergence.tol), o.resume_hint));
    }
  }
  comm.past_collectives();
  if (!root) return;  // rank 0 reports the outcome; main makes every rank exit with its status
  io::commit_in_order({&*csv_out, history_out ? &*history_out : nullptr});
  if (vtk_failure)
    throw io::with_note(*vtk_failure, "the table was written: " + (o.csv == "-" ? std::string("<stdout>") : o.csv));
  if (!stalled.empty()) {
    std::string message;
    for (const auto& s : stalled) message += (message.empty() ? "" : "\n") + s;
    throw ComputationError(message);
  }
}


}  // namespace cmp::flowrun
