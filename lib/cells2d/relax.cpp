#include "cells2d/relax.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::cells2d {

RelaxResult relax(std::vector<Cell>& cells, ContactEngine& engine, const RelaxParameters& p) {
  RelaxResult result;
  const std::size_t n = cells.size();
  const double per_cell = p.tolerance * static_cast<double>(n);
  std::vector<double> scale(n);
  Eigen::VectorXd x(static_cast<Eigen::Index>(3 * n));
  for (std::size_t i = 0; i < n; ++i) {
    scale[i] = std::sqrt(inertia_per_mass(cells[i].bud));
    x[3 * i] = cells[i].x, x[3 * i + 1] = cells[i].y, x[3 * i + 2] = scale[i] * cells[i].theta;
  }
  double energy = 0, previous = 0;
  long evaluations = 0;
  const auto forces = [&](const Eigen::VectorXd& state, Eigen::VectorXd& f) {
    for (std::size_t i = 0; i < n; ++i) {
      cells[i].x = state[3 * i], cells[i].y = state[3 * i + 1], cells[i].theta = state[3 * i + 2] / scale[i];
    }
    previous = energy;
    energy = engine.evaluate(cells, f.data());
    for (std::size_t i = 0; i < n; ++i) f[3 * i + 2] /= scale[i];
    ++evaluations;
  };
  // Rule (ii) at the start: nothing to do (most growth steps below jamming).
  Eigen::VectorXd f(x.size());
  forces(x, f);
  result.evaluations = 1;
  if (energy < per_cell) {
    result.energy = energy;
    result.converged = true;
    return result;
  }
  bool met = false;
  const auto stop_rules = [&](long, double) {
    met = energy < per_cell || (p.force_tolerance <= 0 && std::abs(energy - previous) <= p.tolerance * previous);
    return !met;
  };
  minimise::FireParameters fire = p.fire;
  fire.max_iterations = p.max_iterations;
  fire.force_tolerance = std::max(p.force_tolerance, 0.0);
  const auto r = minimise::fire(x, forces, fire, stop_rules, 1);
  // FIRE's last force evaluation was at x: cells hold x already.
  result.energy = energy;
  result.iterations = r.iterations;
  result.evaluations = evaluations;
  result.converged = met || r.converged();
  return result;
}

RelaxResult relax_or_fail(std::vector<Cell>& cells, ContactEngine& engine, const RelaxParameters& p,
                          const char* what) {
  const RelaxResult r = relax(cells, engine, p);
  if (!r.converged)
    throw ComputationError(std::string(what) + ": the minimisation met no stopping rule in " +
                           std::to_string(p.max_iterations) + " FIRE iterations");
  return r;
}

}  // namespace cmp::cells2d
