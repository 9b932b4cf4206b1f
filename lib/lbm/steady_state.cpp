#include "lbm/steady_state.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmp::lbm {

namespace {

// How far one observable may still be from its limit, relative to its value: the change over
// the last window (d1) and, when the change shrinks geometrically (the window before, d0, of
// the same sign and larger: ratio r = d1/d0), the rest of the geometric series d1 r / (1 - r).
// A change that does not shrink leaves the limit unknown (infinite) unless both changes are at
// round-off (1e-12, or tol / 100 if smaller); a change of sign bounds the rest by the last change.
double remaining(double now, double mid, double then, double tol) {
  const double scale = std::abs(now);
  const double d1 = now - mid, d0 = mid - then, floor = std::min(1e-12, 0.01 * tol) * scale;
  if (std::abs(d1) <= floor && std::abs(d0) <= floor) return std::abs(d1) / scale;
  if (d1 * d0 <= 0) return std::abs(d1) / scale;
  if (std::abs(d1) >= std::abs(d0)) return std::numeric_limits<double>::infinity();
  const double ratio = d1 / d0;
  return std::max(std::abs(d1), std::abs(d1) * ratio / (1 - ratio)) / scale;
}

}  // namespace

std::optional<double> distance_to_steady(const std::vector<FlowObservables>& h, long window) {
  const std::size_t w = static_cast<std::size_t>(window), k = h.size();
  if (w < 1 || k <= 2 * w) return std::nullopt;
  const FlowObservables &now = h[k - 1], &mid = h[k - 1 - w], &then = h[k - 1 - 2 * w];
  return std::max(remaining(now.kappa_lu, mid.kappa_lu, then.kappa_lu, 1e-300),
                  remaining(now.tortuosity, mid.tortuosity, then.tortuosity, 1e-300));
}

bool steady(const std::vector<FlowObservables>& h, const ConvergenceSettings& s) {
  const std::size_t w = static_cast<std::size_t>(s.window), k = h.size();
  if (k <= 2 * w) return false;
  const FlowObservables &now = h[k - 1], &mid = h[k - 1 - w], &then = h[k - 1 - 2 * w];
  if (!(remaining(now.kappa_lu, mid.kappa_lu, then.kappa_lu, s.tol) <= s.tol &&
        remaining(now.tortuosity, mid.tortuosity, then.tortuosity, s.tol) <= s.tol))
    return false;
  // An oscillation (sound waves) whose period is near the window's looks still over a window:
  // every change from one check to the next over the two windows must be below tol too.
  for (std::size_t j = k - 2 * w; j < k; ++j)
    if (std::abs(h[j].kappa_lu - h[j - 1].kappa_lu) > s.tol * std::abs(now.kappa_lu) ||
        std::abs(h[j].tortuosity - h[j - 1].tortuosity) > s.tol * std::abs(now.tortuosity))
      return false;
  return true;
}

SteadyStateResult run_to_steady_state(FlowSolver& solver, const ConvergenceSettings& settings,
                                      const std::function<void(const FlowObservables&)>& on_check,
                                      std::vector<FlowObservables> earlier) {
  if (!(settings.tol > 0) || settings.check_every < 1 || settings.window < 1 || settings.max_steps < 1)
    throw UsageError("convergence settings: tol, check interval, window and step cap must be positive");
  SteadyStateResult r;
  r.history = std::move(earlier);
  auto converged = [&] { return steady(r.history, settings); };
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
