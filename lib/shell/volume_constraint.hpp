#pragma once
// Constant volume held as a constraint (the "projected" volume rule, relax.hpp): every shell's
// volume V_s is kept at its target V0_s throughout a relaxation, and its turgor Pi_s is the
// Lagrange multiplier of that constraint, the pressure at which the shell's force has no part
// along grad V_s. The fixed point is the thesis's (5.2.1: mechanical equilibrium with every
// V_s = V0_s), reached without its loop of relaxations and turgor updates.
//
// Why: towards confluence the volumes answer the turgors both too little (all Pi together:
// the box holds the packing) and too much (between two flattened neighbours), so an update rule
// needs many rounds of relaxation (volume_rule.hpp); as a constraint the volume is never off.
//
// How, inside FIRE (minimise::fire's constraint hook, as RATTLE in constrained dynamics):
// - after each drift, x moves along n_s = grad V_s, each shell on its own, by the Newton step
//   (V0_s - V_s) / |n_s|^2 back onto V_s = V0_s, and the velocity loses its part along n_s;
// - the force is taken without the turgor (its part along n_s is all the turgor gives, and all
//   the projection takes away) and loses its part -Pi_s n_s along n_s: Pi_s is the multiplier,
//   and the projected force is the true force at it, so FIRE's residual is that of the true force.
// A Newton step's direction is the gradient of the last force evaluation: the drift moved x by
// far less than a shell's size, and the next step corrects what is left (the target is V0_s,
// not the last volume, so nothing accumulates). Fixed vertices are left out of n.
// Deterministic: the per-shell sums are added chunk by chunk in order, on any thread count.
#include "shell/turgor_pressure.hpp"

#include <Eigen/Core>

#include <vector>

namespace cmp::shell {

class VolumeConstraint {
 public:
  // `fixed`: the system's fixed-vertex mask (or empty).
  VolumeConstraint(TurgorPressure& pressure, const std::vector<char>& fixed);

  // x onto every V_s = V0_s (Newton steps until max_s |V_s - V0_s| / V0_s <= kTolerance, or one
  // step along the last force's gradients after the first call), v tangent there.
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v);
  // f, the force at x of every term but the turgor, without its part along each n_s at x: the
  // total force at the turgors that make that part vanish, which become the pressure's Pi_s.
  void project_force(const Eigen::VectorXd& x, Eigen::VectorXd& f);

  static constexpr double kTolerance = 1e-12;  // relative volume error the first projection reaches
  static constexpr int kNewtonSteps = 30;      // ... in at most this many steps (cmp::ComputationError beyond)

 private:
  void gradients(const Eigen::VectorXd& x);
  // Per shell: sum over its free vertices of a_i . b_i (3 doubles each).
  void per_shell_dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b, std::vector<double>& out) const;
  void remove_normal(Eigen::VectorXd& y, std::vector<double>& coefficient) const;  // y -= c_s n_s, c_s = y.n_s/|n_s|^2
  // y += sign c_s n_s (sign -1: the same bits as adding -c_s)
  void add_along_normals(const std::vector<double>& coefficient, Eigen::VectorXd& y, double sign = 1.0) const;

  static constexpr long kChunkVertices = 4096;

  TurgorPressure& pressure_;
  const std::vector<char>& fixed_;
  Eigen::VectorXd n_;               // grad V_s per vertex, at the x of the last force (0 at fixed vertices)
  std::vector<double> norm2_;       // |n_s|^2
  std::vector<double> scratch_;
  bool have_gradients_ = false;
  int chunks_;     // fixed chunks of vertices (the per-shell sums: the same bits on any thread count)
  bool parallel_;  // on all threads where the membrane's passes are
  mutable std::vector<std::vector<double>> partial_;  // per chunk, per shell
};

}  // namespace cmp::shell
