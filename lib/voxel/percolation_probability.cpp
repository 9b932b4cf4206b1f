#include "voxel/percolation_probability.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace cmp::voxel {

std::vector<ProbabilityBin> percolation_probability(const std::vector<PercolationSample>& samples, int bins) {
  if (bins < 1) throw std::invalid_argument("percolation_probability: bins must be >= 1");
  std::map<std::pair<int, double>, std::vector<const PercolationSample*>> groups;
  for (const auto& s : samples) groups[{s.particles, s.delta}].push_back(&s);
  std::vector<ProbabilityBin> out;
  for (const auto& [key, group] : groups) {
    double lo = group.front()->porosity, hi = lo;
    for (const auto* s : group) {
      lo = std::min(lo, s->porosity);
      hi = std::max(hi, s->porosity);
    }
    const int nb = hi > lo ? bins : 1;
    const double width = hi > lo ? (hi - lo) / nb : 0.0;
    std::vector<ProbabilityBin> b(nb);
    for (int k = 0; k < nb; ++k) {
      b[k].particles = key.first;
      b[k].delta = key.second;
      b[k].porosity_low = lo + k * width;
      b[k].porosity_high = k + 1 == nb ? hi : lo + (k + 1) * width;
    }
    for (const auto* s : group) {
      const int k = width > 0 ? std::min(nb - 1, static_cast<int>((s->porosity - lo) / width)) : 0;
      ++b[k].packings;
      b[k].percolating += s->percolates;
      b[k].porosity_mean += s->porosity;
    }
    for (auto& bin : b) {
      if (bin.packings == 0) continue;
      bin.porosity_mean /= bin.packings;
      bin.probability = static_cast<double>(bin.percolating) / bin.packings;
      bin.probability_error = std::sqrt(bin.probability * (1 - bin.probability) / bin.packings);
      out.push_back(bin);
    }
  }
  return out;
}

}  // namespace cmp::voxel
