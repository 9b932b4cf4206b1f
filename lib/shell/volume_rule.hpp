#pragma once
// The constant-volume update of the turgors: the thesis's Pi_s <- Pi_s (1 + e_s),
// e_s = (V0_s - V_s)/V_s (5.2.1), or the same with its two slow ways out taken away.
//
// The thesis's rule closes, per update, the fraction c = d ln V / d ln Pi of a volume gap, and
// towards confluence that fraction is wrong in both directions:
// - The common mode: the box leaves the packing as a whole little room, so raising every Pi
//   together barely changes any volume (c ~ 0.03 on 16 x 642 shells at phi 0.94). The errors of
//   all shells keep one sign and shrink by a few per cent per update: 40-150 updates per box
//   step, each followed by more relaxation.
// - The differences: between two flattened neighbours volume moves easily, and a shell whose
//   volume answers its Pi by more than twice the gap (c > 2) overshoots by more each time: the
//   errors of a pair swing from +0.2 % to -0.4 % to +0.8 % (50 x 2,562 shells at phi 0.94).
// So the accelerated rule splits e_s into its mean e and the differences e_s - e:
//   Pi_s <- Pi_s (1 + h_s (e_s - e) + g e).
// g comes from how the mean answered the last update (a damped secant on one number): that
// update moved ln Pi by g' e' on average and the mean fell from e' to e, so c ~ (e' - e)/(g' e')
// and g = kClose / c closes kClose of the gap next time. g is at least 1 (never slower than the
// thesis), at most doubles per update, and is re-estimated only while the mean stands out of
// the differences. h_s starts at 1 (the thesis's gain) and halves each time e_s - e flips sign
// without halving (an overshoot), growing back by half while it keeps its sign. One update
// moves a Pi by at most kLargestStep. The fixed point is the thesis's (every V_s within the
// tolerance of V0_s); only the number of updates to it changes. A rule starts afresh for each
// relaxation (a box step), so nothing beyond the turgors needs checkpointing.
#include "shell/turgor_pressure.hpp"

#include <span>
#include <string>
#include <vector>

namespace cmp::shell {

// Projected: no update rule; the volumes are held as constraints and each Pi is the
// multiplier (volume_constraint.hpp), the same fixed point.
enum class VolumeRuleKind { Thesis, Accelerated, Projected };
// "thesis" / "accelerated" / "projected"; the parser throws cmp::UsageError for another name.
std::string volume_rule_name(VolumeRuleKind kind);
VolumeRuleKind parse_volume_rule(const std::string& name);

class VolumeRule {
 public:
  explicit VolumeRule(VolumeRuleKind kind = VolumeRuleKind::Accelerated) : kind_(kind) {}
  // The turgors after one update, from the turgors pi, volumes v and targets v0 of every shell.
  std::vector<double> next(const std::vector<double>& pi, const std::vector<double>& v, const std::vector<double>& v0);
  // One update of every shell's Pi at x.
  void update(TurgorPressure& pressure, std::span<const double> x) {
    pressure.set_turgors(next(pressure.turgors(), pressure.volumes(x), pressure.target_volumes()));
  }
  double common_gain() const { return gain_; }
  const std::vector<double>& difference_gains() const { return damping_; }

  static constexpr double kClose = 0.5;         // the fraction of the mean gap one update aims to close
  static constexpr double kLargestGain = 64;    // g at most this
  static constexpr double kLargestStep = 0.2;   // |relative change of Pi| per update
  static constexpr double kClearMean = 0.25;    // g is re-estimated only where |e'| > this * max_s |e'_s - e'|
  static constexpr double kSmallestDamping = 1.0 / 16;  // h_s at least this

 private:
  VolumeRuleKind kind_;
  double gain_ = 1, last_mean_ = 0, last_spread_ = 0;  // the last update's g, e and max_s |e_s - e|
  std::vector<double> damping_, last_difference_;      // per shell: h_s, and e_s - e at the last update
};

}  // namespace cmp::shell
