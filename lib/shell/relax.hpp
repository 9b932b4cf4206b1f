#pragma once
// Statics and over-damped dynamics of a shell system (thesis B.3-B.4).
//
// Statics: FIRE (lib/minimise, the thesis's parameters) on the system's state. The thesis
// stops at max_i |f_i| <= 1e-15, an absolute force in whatever units the run uses; here the
// tolerance is relative: max_i |f_i| <= relative_tolerance * force_scale, with the force scale
// E t a (the force of a unit strain on one vertex: a the mean rest edge length), so the same
// setting means the same thing in Pa and m, MPa and um, or E = 1. The fictitious mass of every
// coordinate is set from the stiffest mode of the start state (a power iteration on the
// Hessian), so FIRE's time steps (dt_max = 1.5) are stable whatever the units and the mesh.
//
// Constant volume (TurgorPressure with PressureControl::ConstantVolume, 5.2.1), by default
// (VolumeRuleKind::Projected): every volume held at its target inside FIRE, each Pi the
// constraint's multiplier (volume_constraint.hpp), one FIRE run with no updates. The thesis's
// loop and the accelerated rule instead: relax, and while some shell is off its target volume
// by more than 0.1 %, update its Pi by Pi <- Pi (1 + (V0 - V)/V) and relax again. The same fixed point is reached with far fewer
// iterations when Pi moves while x relaxes: once FIRE's residual is below
// volume_update_factor times the force tolerance (x near equilibrium for the current Pi, so
// V answers to it), the volumes are checked every volume_update_interval iterations and at
// convergence, and a shell off by more than the tolerance gets the update there and then; the
// next update inside FIRE then waits for a residual no higher (shell/volume_update_window.hpp).
// FIRE stops only at the force tolerance with every volume within its tolerance (or a whole
// relaxation follows, as in the thesis's loop), and every Pi update counts in volume_updates.
//
// Dynamics: Heun's method (explicit trapezoid, the thesis's integrator for B.5) of
// mu dx/dt = F(x), mu the damping coefficient (the thesis fixes mu = 1).
#include "shell/shell_system.hpp"
#include "shell/volume_rule.hpp"

#include "minimise/fire.hpp"

#include <cmath>
#include <functional>
#include <string>

namespace cmp::shell {

struct RelaxParameters {
  minimise::FireParameters fire;     // its force_tolerance and mass are set by relax()
  double relative_tolerance = 1e-7;  // stop when max_i |f_i| <= this * force_scale
  double force_scale = 1.0;          // [force]; default_force_scale() for a shell
  double mass_factor = 1.0;          // FIRE mass = this * lambda_max * (dt_max / 1.5)^2: dt_max stable with margin 4/3
  double volume_tolerance = 1e-3;    // constant volume: |V - V0| <= this * V0
  int max_volume_updates = 500;      // constant volume: Pi updates before giving up (0: Pi held, the volumes free)
  double volume_update_factor = 100; // constant volume: Pi moves inside FIRE once max|f_i| <= this * the tolerance
  int volume_update_interval = 20;   // ... checked every this many FIRE iterations (and at convergence)
  VolumeRuleKind volume_rule = VolumeRuleKind::Projected;  // constant volume: how Pi moves (volume_rule.hpp)
  // Throws cmp::UsageError naming the first bad field.
  void validate() const;
  // Whether a constant-volume pressure holds its volumes: not with no updates allowed or an
  // infinite tolerance (an inflation at fixed Pi), whatever the rule.
  bool holds_volume() const { return max_volume_updates > 0 && std::isfinite(volume_tolerance); }
};

// E t a: Young's modulus times thickness times the mean rest edge length of the mesh.
double default_force_scale(const mesh::TriMesh& rest, double youngs_modulus, double thickness);

// The largest eigenvalue of the Hessian of the system's energy at x (fixed vertices left
// out), by `steps` Lanczos steps on finite differences of the forces (two force evaluations
// each). [force / length]
double stiffest_mode(const ShellSystem& s, const Eigen::VectorXd& x, int steps = 12);

enum class RelaxStop { Converged, MaxIterations, VolumeUpdates, Interrupted };
std::string relax_stop_name(RelaxStop stop);

struct RelaxResult {
  RelaxStop stop = RelaxStop::MaxIterations;
  long iterations = 0;         // FIRE iterations over every relaxation
  long force_evaluations = 0;
  int volume_updates = 0;      // constant volume: Pi updates made
  double residual = 0;         // max_i |f_i| / force_scale at the end
  double volume_error = 0;     // constant volume: max_s |V_s - V0_s| / V0_s at the end (0 otherwise)
  bool converged() const { return stop == RelaxStop::Converged; }
};

// Called now and then with (FIRE iterations so far, current residual); false interrupts.
using RelaxProgress = std::function<bool(long iterations, double residual)>;

// Relaxes s.x to mechanical equilibrium (and, for a constant-volume pressure, to its target
// volumes). Throws cmp::ComputationError when a force becomes non-finite.
RelaxResult relax(ShellSystem& s, const RelaxParameters& p, const RelaxProgress& progress = {});

// One Heun step of mu dx/dt = F(x) of size dt on s.x (fixed vertices stay).
void heun_step(ShellSystem& s, double dt, double damping = 1.0);

struct HeunResult {
  long steps = 0;
  double residual = 0;  // max_i |f_i| / force_scale at the end
  bool converged = false;
};
// Heun steps until max_i |f_i| <= relative_tolerance * force_scale or max_steps.
HeunResult heun_relax(ShellSystem& s, double dt, double damping, double relative_tolerance, double force_scale,
                      long max_steps);

}  // namespace cmp::shell
