#include "shell/volume_rule.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::shell {

std::string volume_rule_name(VolumeRuleKind kind) {
  switch (kind) {
    case VolumeRuleKind::Thesis: return "thesis";
    case VolumeRuleKind::Accelerated: return "accelerated";
    case VolumeRuleKind::Projected: return "projected";
  }
  return "?";
}

VolumeRuleKind parse_volume_rule(const std::string& name) {
  if (name == "thesis") return VolumeRuleKind::Thesis;
  if (name == "accelerated") return VolumeRuleKind::Accelerated;
  if (name == "projected") return VolumeRuleKind::Projected;
  throw UsageError("must be accelerated, projected or thesis, got '" + name + "'");
}

std::vector<double> VolumeRule::next(const std::vector<double>& pi, const std::vector<double>& v,
                                     const std::vector<double>& v0) {
  const std::size_t shells = pi.size();
  std::vector<double> out = pi;
  if (kind_ == VolumeRuleKind::Thesis) {
    for (std::size_t s = 0; s < shells; ++s) out[s] *= 1.0 + (v0[s] - v[s]) / v[s];
    return out;
  }
  std::vector<double> error(shells);
  double mean = 0;
  for (std::size_t s = 0; s < shells; ++s) {
    error[s] = (v0[s] - v[s]) / v[s];
    mean += error[s];
  }
  mean /= static_cast<double>(std::max<std::size_t>(shells, 1));
  double spread = 0;
  for (std::size_t s = 0; s < shells; ++s) spread = std::max(spread, std::abs(error[s] - mean));
  // The secant on the mean, only where it stood out of the differences last time (else it
  // measures their noise).
  double gain = gain_;
  if (last_mean_ != 0 && std::abs(last_mean_) > kClearMean * last_spread_) {
    const double closed = (last_mean_ - mean) / (gain_ * last_mean_);  // c, from the last update
    if (closed > 0) gain = std::clamp(kClose / closed, 1.0, std::min(2 * gain_, kLargestGain));
  }
  if (damping_.size() != shells) {
    damping_.assign(shells, 1.0);
    last_difference_.assign(shells, 0.0);
  }
  for (std::size_t s = 0; s < shells; ++s) {
    const double difference = error[s] - mean, last = last_difference_[s];
    if (difference * last < 0 && std::abs(difference) > 0.5 * std::abs(last))
      damping_[s] = std::max(damping_[s] * 0.5, kSmallestDamping);
    else if (difference * last > 0)
      damping_[s] = std::min(damping_[s] * 1.5, 1.0);
    last_difference_[s] = difference;
    out[s] *= 1.0 + std::clamp(damping_[s] * difference + gain * mean, -kLargestStep, kLargestStep);
  }
  gain_ = gain;
  last_mean_ = mean;
  last_spread_ = spread;
  return out;
}

}  // namespace cmp::shell
