#pragma once
// Running a FlowSolver until kappa and tau_H stop changing.
#include "lbm/flow_solver.hpp"

#include <functional>
#include <vector>

namespace cmp::lbm {

struct ConvergenceSettings {
  double tol = 1e-6;       // relative change of kappa and of tau_H over the window
  long check_every = 100;  // steps between checks (even values keep checks on the same AA parity)
  long window = 10;        // checks: compare the current check with the one `window` checks earlier
  long max_steps = 200000; // step cap
};

struct SteadyStateResult {
  FlowObservables final;
  bool converged = false;
  std::vector<FlowObservables> history;  // one entry per check
};

// Steps until |kappa - kappa_prev| <= tol |kappa| and |tau_H - tau_H_prev| <= tol tau_H, where
// _prev is the check `window` checks earlier, or until max_steps (converged = false). Starts
// from the solver's current step count (a resumed run continues its count). on_check is
// called after every check (progress bar, --history, checkpoint timer); may be empty. Throws
// cmp::ComputationError if the flow blows up (a non-finite observable). `earlier`: the checks
// of an interrupted run (what FlowSolver::load returned), so a resumed run stops at the same
// step with the same result as an uninterrupted one.
SteadyStateResult run_to_steady_state(FlowSolver& solver, const ConvergenceSettings& settings,
                                      const std::function<void(const FlowObservables&)>& on_check = {},
                                      std::vector<FlowObservables> earlier = {});

// A solver on `lattice` run to steady state: the whole computation of a permeability check
// (benchmarks, tests, a one-image run without checkpoints).
SteadyStateResult solve_steady(const PoreLattice& lattice, const FlowSettings& settings,
                               const ConvergenceSettings& convergence);

}  // namespace cmp::lbm
