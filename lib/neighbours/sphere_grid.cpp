#include "neighbours/sphere_grid.hpp"

#include "core/errors.hpp"

#include <string>

namespace cmp::neighbours {

CellGrid make_sphere_grid(double radius, double cutoff, const Eigen::Vector3d& centre) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw UsageError("sphere grid: the radius must be positive and finite, got " + std::to_string(radius));
  Box box;
  box.lower = centre.array() - radius;
  box.lengths.setConstant(2 * radius);
  return CellGrid(box, cutoff);
}

}  // namespace cmp::neighbours
