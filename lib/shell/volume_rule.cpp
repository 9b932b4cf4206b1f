#include "shell/volume_rule.hpp"

#include <algorithm>

namespace cmp::shell {

void VolumeRule::update(TurgorPressure& pressure, std::span<const double> x) {
  const auto v = pressure.volumes(x);
  const auto& target = pressure.target_volumes();
  std::vector<double> pi = pressure.turgors();
  for (std::size_t s = 0; s < v.size(); ++s) {
    const double error = (target[s] - v[s]) / v[s];
    if (error * last_[s] > 0)
      gain_[s] = std::min(gain_[s] * kGrowth, kLargestGain);
    else if (error * last_[s] < 0)
      gain_[s] = std::max(gain_[s] * 0.5, 1.0);
    last_[s] = error;
    pi[s] *= 1.0 + std::clamp(gain_[s] * error, -kLargestStep, kLargestStep);
  }
  pressure.set_turgors(pi);
}

}  // namespace cmp::shell
