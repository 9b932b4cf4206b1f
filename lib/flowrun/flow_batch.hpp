#pragma once
// lbflow's whole job over its inputs: every input read and checked first (a bad or
// non-percolating one stops the batch before any output exists), then one flow each, one CSV
// row each, the history and VTK fields on request, the summaries and warnings on stderr.
#include "flowrun/flow_case.hpp"
#include "flowrun/flow_run.hpp"

#include <string>
#include <vector>

namespace cmp::flowrun {

struct FlowBatch {
  std::vector<std::string> inputs;
  InputOptions input;
  std::vector<int> refinements;        // --refine M1,M2,...: one run per M (empty: input.refine)
  bool prolong = false;                // each M after the first started from the flow of the one before
  RunPlan run;
  std::vector<std::string> vtk_names;  // one per input; empty strings: no --vtk
  std::string csv = "-";               // the table ('-': stdout)
  std::string history;                 // per-check table ("" none)
  bool timings = false;                // seconds and MLUPS columns and summaries
  bool quiet = false;                  // no summary lines
  std::string drop_option;             // the option that lowers the drive, named in the Stokes warning
  std::string resume_hint;             // said after a step cap ("" none)
};

// Runs the batch; writes the outputs atomically. Throws cmp::ComputationError naming every
// input that hit the step cap (after its row is written), and what read_flow_case and FlowRun throw.
void run_flow_batch(const FlowBatch& batch, const std::string& provenance);

}  // namespace cmp::flowrun
