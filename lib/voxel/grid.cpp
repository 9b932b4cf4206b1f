#include "voxel/grid.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace cmp::voxel {

VoxelGrid make_grid(const Eigen::Vector3d& box, double delta, std::array<bool, 3> periodic) {
  if (!(delta > 0) || !std::isfinite(delta)) throw UsageError(fmt::format("--delta must be positive, got {}", delta));
  for (int a = 0; a < 3; ++a)
    if (!(box[a] > 0) || !std::isfinite(box[a])) throw UsageError(fmt::format("box side {} is not positive", box[a]));
  if (delta > box.minCoeff())
    throw UsageError(fmt::format("--delta {} is larger than the box (smallest side {})", delta, box.minCoeff()));
  VoxelGrid g;
  g.box = box;
  g.periodic = periodic;
  double total = 1;
  for (int a = 0; a < 3; ++a) {
    const double n = std::max(1.0, std::nearbyint(box[a] / delta));
    total *= n;
    if (total >= 2147483647.0)
      throw UsageError(fmt::format("--delta {} gives {} voxels or more; at most 2^31 - 2 are supported", delta, total));
    g.dims[a] = static_cast<int>(n);
    g.spacing[a] = box[a] / n;
  }
  return g;
}

}  // namespace cmp::voxel
