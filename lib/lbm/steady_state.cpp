#include "lbm/steady_state.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <string>

namespace cmp::lbm {

SteadyStateResult run_to_steady_state(FlowSolver& solver, const ConvergenceSettings& settings,
                                      const std::function<void(const FlowObservables&)>& on_check,
                                      std::vector<FlowObservables> earlier) {
  if (!(settings.tol > 0) || settings.check_every < 1 || settings.window < 1 || settings.max_steps < 1)
    throw UsageError("convergence settings: tol, check interval, window and step cap must be positive");
  SteadyStateResult r;
  r.history = std::move(earlier);
  auto converged = [&] {
    const std::size_t k = r.history.size();
    if (k <= static_cast<std::size_t>(settings.window)) return false;
    const FlowObservables& now = r.history[k - 1];
    const FlowObservables& then = r.history[k - 1 - static_cast<std::size_t>(settings.window)];
    return std::abs(now.kappa_lu - then.kappa_lu) <= settings.tol * std::abs(now.kappa_lu) &&
           std::abs(now.tortuosity - then.tortuosity) <= settings.tol * std::abs(now.tortuosity);
  };
  r.converged = converged();
  while (!r.converged && solver.steps() < settings.max_steps) {
    solver.step(std::min(settings.check_every, settings.max_steps - solver.steps()));
    const FlowObservables o = solver.observe();
    if (!std::isfinite(o.kappa_lu) || !std::isfinite(o.tortuosity) || !std::isfinite(o.mass))
      throw ComputationError("the flow blew up after " + std::to_string(o.steps) +
                             " steps (non-finite velocity): lower the pressure drop or raise tau");
    r.history.push_back(o);
    if (on_check) on_check(o);
    r.converged = converged();
  }
  r.final = r.history.empty() ? solver.observe() : r.history.back();
  return r;
}

SteadyStateResult solve_steady(const PoreLattice& lattice, const FlowSettings& settings,
                               const ConvergenceSettings& convergence) {
  FlowSolver solver(lattice, settings);
  return run_to_steady_state(solver, convergence);
}

}  // namespace cmp::lbm
