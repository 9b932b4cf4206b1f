#pragma once
// Running a FlowSolver until kappa and tau_H stop changing.
#include "lbm/flow_solver.hpp"

#include <functional>
#include <optional>
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

// The steady-state test on the checks so far: for kappa and for tau_H, the change d1 over the
// last `window` checks is at most tol (relative), and so is the estimated distance to the limit,
// the rest of the geometric series when the change shrinks (d1 r / (1 - r), r = d1 / d0 with
// d0 the change over the window before; a change that does not shrink is not steady unless both
// are at round-off), and every change from one check to the next over the two windows is below
// tol (an oscillation with the window's period looks still over a window). A flow that creeps slowly (r near 1) therefore runs on until the rest
// of its creep is below tol, where the change over one window alone would stop it early.
bool steady(const std::vector<FlowObservables>& history, const ConvergenceSettings& settings);
// That estimated distance to the limit (relative, the larger of kappa's and tau_H's; infinite
// when the change does not shrink), or nullopt before 2 windows of checks.
std::optional<double> distance_to_steady(const std::vector<FlowObservables>& history, long window);

// Steps until steady(), or until max_steps (converged = false). Starts
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
