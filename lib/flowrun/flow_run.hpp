#pragma once
// One lbflow run: a FlowCase through the flow solver to steady state, with the progress bar,
// the periodic checkpoint and the resume, and the flow field for --vtk.
#include "flowrun/flow_case.hpp"
#include "flowrun/flow_table.hpp"
#include "flowrun/flow_vtk.hpp"
#include "flowrun/prolong.hpp"
#include "lbm/flow_solver.hpp"
#include "lbm/steady_state.hpp"

#include <memory>
#include <string>
#include <vector>

namespace cmp::flowrun {

struct RunPlan {
  lbm::FlowSettings flow;
  lbm::ConvergenceSettings convergence;
  std::string checkpoint;                    // checkpoint file ("" none)
  double checkpoint_every = 300;             // seconds between checkpoints (0: at every check)
  std::vector<std::string> checkpoint_args;  // the arguments that define the run (stored in it)
  std::string resume;                        // checkpoint to continue from ("" none)
  bool quiet = false;                        // no progress bar
  lbm::Communicator comm;                    // the ranks the flow runs on (one process by default)
};

class FlowRun {
 public:
  // Builds the lattice (c.make_lattice()) and the solver; with plan.resume, loads its state
  // (throws cmp::InputError when it is from another run). Throws what lbm::FlowSolver throws.
  // On several ranks (plan.comm) every member is a collective call; only rank 0 shows the
  // progress bar, writes the checkpoint and gets the field.
  FlowRun(FlowCase& c, const RunPlan& plan);
  ~FlowRun();
  // Steps to steady state or the step cap; a progress bar (steps, kappa, its change) on a
  // terminal; the checkpoint every plan.checkpoint_every seconds and once at the end.
  FlowOutcome run();
  // Starts from a guess of the steady flow instead of rest (before run(); not with a resume).
  void start_from(const lbm::StartState& state);
  // The flow reached, on every rank, as the start of a finer lattice (prolonged_start). Collective.
  CoarseFlow coarse_flow() const;
  // Velocity and density on every node, in the input's geometry, for write_flow_vtk; field
  // data delta, d0, scale (when known), refine, permeability_lu, tortuosity.
  FlowField field(const FlowOutcome& outcome) const;

 private:
  FlowCase& case_;
  const RunPlan& plan_;
  std::unique_ptr<lbm::FlowSolver> solver_;
  std::vector<lbm::FlowObservables> earlier_;
};

}  // namespace cmp::flowrun
