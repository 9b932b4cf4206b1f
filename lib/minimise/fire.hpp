#pragma once
// FIRE, the fast inertial relaxation engine (Bitzek et al., PRL 97, 170201, 2006), as the
// thesis runs it (Algorithm 4 of B.4.1; parameters of 5.5.1): velocity Verlet with
// unit mass, then the velocity is turned towards the force, the time step grows while the
// power P = v.F stays positive and the system restarts from rest when it turns negative.
//
//   minimise::FireParameters p;             // the thesis's values
//   p.force_tolerance = 1e-12;
//   auto result = minimise::fire(x, [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
//     ... f = -grad E(x) ...
//   }, p);
//
// The minimiser sees only a flat state vector; particles are consecutive blocks of
// `block_size` coordinates, and convergence is judged on the largest block norm (the largest
// force on any one particle or vertex), as "max |f_i|" in the thesis.
#include <Eigen/Core>

#include <functional>
#include <string>

namespace cmp::minimise {

// From this many coordinates on, FIRE's vector passes are cut into kFireChunks fixed chunks
// whose sums are added in order (on all threads from FireParameters::parallel_size): the same
// path for any thread count.
inline constexpr Eigen::Index kParallelFireSize = 3 * 2048;
inline constexpr int kFireChunks = 4;

struct FireParameters {
  double dt = 0.1;             // initial time step, dt_FIRE
  double dt_max = 1.5;         // largest time step, dt_FIRE^max
  double alpha_start = 0.1;    // initial velocity mixing, alpha_FIRE
  int n_min = 5;               // steps with P > 0 before dt may grow, N_min
  double f_alpha = 0.99;       // alpha shrink factor while P > 0
  double f_inc = 1.1;          // time step growth while P > 0
  double f_dec = 0.25;         // time step shrink when P <= 0 (the thesis's; Bitzek uses 0.5)
  double mass = 1.0;           // fictitious mass of every coordinate (the thesis does not say)
  double force_tolerance = 1e-12;  // stop when max_i |f_i| <= this (thesis: 1e-15, absolute)
  long max_iterations = 10'000'000;
  int block_size = 3;          // coordinates per particle for |f_i|
  // From this many coordinates on, the vector passes run on all threads (below, the same
  // chunks in order on one: same bits). kParallelFireSize suits forces as cheap as spheres';
  // a caller whose own force passes stay on one thread up to a larger size passes that size.
  long parallel_size = kParallelFireSize;
  // A step that multiplies max |f_i| by more than this is a local instability that the global
  // power P misses (a few vertices ringing beyond their stability limit while the rest of the
  // system still flows downhill): restart from rest as for P <= 0 and keep dt below half the
  // step that rang for the rest of the run. 0 turns the guard off.
  double divergence_factor = 4.0;
  // ... and after this many iterations without ringing, the cap grows back by f_inc per step
  // with P > 0 towards dt_max: near convergence, where max |f_i| is a few vertices, a contact
  // that closes or a Pi update can multiply it by 4 at a step well below the stability limit,
  // and a cap kept for good then made a whole rearrangement crawl at an eighth of the step
  // (50 shells of 2,562 vertices, one box step past 55,000 iterations). Real ringing comes
  // back within a few steps of the cap's lifting and is cut again. 0 keeps the cap for good.
  long dt_max_recovery = 100;

  // Throws cmp::UsageError naming the first bad field (non-positive steps, f_dec >= 1, ...).
  void validate() const;
};

enum class FireStop { ForceTolerance, MaxIterations, Interrupted };
std::string fire_stop_name(FireStop stop);

struct FireResult {
  FireStop stop = FireStop::MaxIterations;
  long iterations = 0;        // velocity Verlet steps (force evaluations after the first)
  long force_evaluations = 0;
  double max_force = 0;       // max_i |f_i| at the end
  long divergence_restarts = 0;  // restarts by FireParameters::divergence_factor
  bool converged() const { return stop == FireStop::ForceTolerance; }
};

// forces(x, f) fills f (same size as x) with minus the gradient of the energy at x.
using ForceFunction = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& f)>;
// Called every `progress_every` iterations with (iterations, max|f_i|); returning false stops
// the minimisation with FireStop::Interrupted.
using FireProgress = std::function<bool(long iterations, double max_force)>;

// Called at the top of every iteration, before the convergence test, with (iterations,
// max|f_i|); returns true when it has changed the force field itself (a constant-volume
// driver moving Pi while x relaxes), and the forces are then evaluated afresh at the same x
// (the velocity is kept).
using FireAdjust = std::function<bool(long iterations, double max_force)>;

// Called after every drift (and once before the first force evaluation, with v = 0) to put x
// back on a constraint surface and v into its tangent space (shell/volume_constraint.hpp); the
// forces function then returns forces tangent to it. Empty: unconstrained.
using FireConstraint = std::function<void(Eigen::VectorXd& x, Eigen::VectorXd& v)>;

// Relaxes x in place until max_i |f_i| <= force_tolerance or max_iterations steps.
// x.size() must be a multiple of block_size. Deterministic: the same x and forces give the
// same path, whatever the thread count. Cost per iteration: one force evaluation plus
// O(size) vector work.
FireResult fire(Eigen::VectorXd& x, const ForceFunction& forces, const FireParameters& parameters,
                const FireProgress& progress = {}, long progress_every = 1000, const FireAdjust& adjust = {},
                const FireConstraint& constrain = {});

// max_i |f_i| over consecutive blocks of block_size coordinates.
double max_block_norm(const Eigen::VectorXd& f, int block_size);

}  // namespace cmp::minimise
