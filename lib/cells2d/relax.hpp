#pragma once
// Energy minimisation of a set of cells with the thesis's stopping rules (3.4.1): stop when
// (i) two successive steps give nearly the same energy, |V_{j+1} - V_j| <= tol V_j, or (ii) the
// energy per cell V_j/(kN) < tol, with tol = eps_tol^2 = 1e-16.
//
// The state is (x_i, y_i, sqrt(I_i/M_i) theta_i) per cell: the thesis's mass-metric gradient
// {F_x, F_y, (M/I) T} in coordinates where FIRE's unit masses are the cells' true masses and
// moments of inertia. The minimiser is lib/minimise's FIRE (the thesis used conjugate
// gradients; both stop on the same rules, so the packings meet the same criterion).
#include "cells2d/cell.hpp"
#include "cells2d/contacts.hpp"
#include "minimise/fire.hpp"

#include <string>
#include <vector>

namespace cmp::cells2d {

struct RelaxParameters {
  double tolerance = 1e-16;       // eps_tol^2 of both stopping rules
  long max_iterations = 2'000'000;
  // When positive, rule (i) is replaced by max_i |f_i| <= force_tolerance [k sigma] (FIRE's
  // own test on (F_x, F_y, T/sqrt(I/M))): what the moduli need, whose 1e-8 perturbations
  // change the energy by less than rule (i) can see.
  double force_tolerance = 0;
  minimise::FireParameters fire = default_fire();

  // FIRE's steps for this model's stiffness (unit k, unit mass per cell).
  static minimise::FireParameters default_fire() {
    minimise::FireParameters p;
    p.dt = 0.1;
    p.dt_max = 0.5;
    p.force_tolerance = 0;
    p.block_size = 3;
    return p;
  }
};

struct RelaxResult {
  double energy = 0;     // V at the end [k sigma^2]
  long iterations = 0;   // FIRE steps (0 when the start already met rule (ii))
  long evaluations = 0;  // force evaluations
  bool converged = false;  // a stopping rule was met (not max_iterations)
};

// Relaxes cells in place (positions and angles; buds unchanged). Throws
// cmp::ComputationError on a non-finite force. The engine must hold the cells' box.
RelaxResult relax(std::vector<Cell>& cells, ContactEngine& engine, const RelaxParameters& parameters);
// relax(), and cmp::ComputationError naming `what` when no stopping rule is met within
// max_iterations.
RelaxResult relax_or_fail(std::vector<Cell>& cells, ContactEngine& engine, const RelaxParameters& parameters,
                          const char* what);

}  // namespace cmp::cells2d
