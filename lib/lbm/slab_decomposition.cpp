// The balanced cut of the slabs over ranks (lbm/slab_decomposition.hpp).
#include "lbm/slab_decomposition.hpp"

#include "core/errors.hpp"
#include "lbm/layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::lbm {

int slab_count(int planes) { return (planes + kBrickPlanes - 1) / kBrickPlanes; }

int SlabDecomposition::owner(int slab) const {
  const auto it = std::upper_bound(first_slab.begin(), first_slab.end(), slab);
  return static_cast<int>(it - first_slab.begin()) - 1;
}

SlabDecomposition decompose_slabs(const std::vector<long>& fluid, int ranks) {
  const int K = static_cast<int>(fluid.size());
  if (ranks < 1) throw UsageError("at least one rank is needed, got " + std::to_string(ranks));
  if (ranks > K)
    throw UsageError(std::to_string(ranks) + " ranks but only " + std::to_string(K) + " slab" + (K == 1 ? "" : "s") +
                     " of " + std::to_string(kBrickPlanes) + " planes along the flow axis: run on at most " +
                     std::to_string(K) + " ranks");
  std::vector<double> before(static_cast<std::size_t>(K) + 1, 0.0);  // fluid nodes before slab k
  for (int k = 0; k < K; ++k) before[static_cast<std::size_t>(k) + 1] = before[static_cast<std::size_t>(k)] + static_cast<double>(fluid[static_cast<std::size_t>(k)]);
  const double total = before.back();
  SlabDecomposition d;
  d.first_slab.assign(static_cast<std::size_t>(ranks) + 1, 0);
  d.first_slab.back() = K;
  for (int r = 1; r < ranks; ++r) {
    const double target = total * r / ranks;
    // Each rank before and after keeps at least one slab.
    const int lo = d.first_slab[static_cast<std::size_t>(r) - 1] + 1, hi = K - (ranks - r);
    int best = lo;
    for (int k = lo; k <= hi; ++k)
      if (std::abs(before[static_cast<std::size_t>(k)] - target) < std::abs(before[static_cast<std::size_t>(best)] - target)) best = k;
    d.first_slab[static_cast<std::size_t>(r)] = best;
  }
  return d;
}

}  // namespace cmp::lbm
