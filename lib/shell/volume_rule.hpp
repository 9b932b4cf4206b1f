#pragma once
// The constant-volume update of the turgor, shell by shell: Pi <- Pi (1 + g (V0 - V)/V).
// With g = 1 this is the thesis's rule (5.2.1). It converges to V = V0 at the rate at which a
// shell's volume answers its pressure: a free shell answers quickly, but a shell squeezed
// between neighbours barely changes its volume with Pi, and the rule then creeps towards the
// target by a small fraction of the error each time (towards confluence hundreds of updates
// per box step, each followed by more relaxation). So each shell's g adapts: it grows by half
// each time the error keeps its sign (the update fell short) and halves, down to 1, when the
// sign flips (it overshot), and one update moves Pi by at most a fifth. The fixed point is the
// thesis's, V = V0 within the tolerance; only the number of updates to it changes. Gains start
// at 1 for each relaxation (a box step), so nothing beyond the turgors needs checkpointing.
#include "shell/turgor_pressure.hpp"

#include <span>
#include <vector>

namespace cmp::shell {

class VolumeRule {
 public:
  explicit VolumeRule(int shells) : gain_(static_cast<std::size_t>(shells), 1.0), last_(gain_.size(), 0.0) {}
  // One update of every shell's Pi at x.
  void update(TurgorPressure& pressure, std::span<const double> x);
  const std::vector<double>& gains() const { return gain_; }

  static constexpr double kGrowth = 1.5;      // gain factor after an update that fell short
  static constexpr double kLargestGain = 64;  // ... up to this
  static constexpr double kLargestStep = 0.2; // |relative change of Pi| per update

 private:
  std::vector<double> gain_, last_;  // per shell: gain, relative error at the last update
};

}  // namespace cmp::shell
