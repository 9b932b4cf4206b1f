#pragma once
// An axis-aligned simulation box, periodic or not along each axis, and the minimum image.
#include "core/minimum_image.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace cmp::neighbours {

// The box [lower, lower + lengths) with per-axis periodic flags.
// A 2D system is a box whose z length is 0 (or anything) and not periodic along z: every point
// then falls in a single layer of cells, whatever its z (make_planar_box does this).
struct Box {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d lengths = Eigen::Vector3d::Ones();
  std::array<bool, 3> periodic{false, false, false};

  // d reduced to its minimum image along the periodic axes: each component in [-L/2, L/2]
  // (ties at exactly L/2 go either way). Works for any d, not only |d| < L.
  Eigen::Vector3d minimum_image(Eigen::Vector3d d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) d[a] = cmp::minimum_image(d[a], lengths[a]);
    return d;
  }

  // p moved into [lower, lower + lengths) along the periodic axes (others untouched).
  Eigen::Vector3d wrap(Eigen::Vector3d p) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) {
        const double s = (p[a] - lower[a]) / lengths[a];
        p[a] = lower[a] + lengths[a] * (s - std::floor(s));
        if (p[a] >= lower[a] + lengths[a]) p[a] = lower[a];  // s just below an integer
      }
    return p;
  }
};

// The box [lower, lower + lengths) of the plane z = 0, seen as a 3D box of zero height.
inline Box make_planar_box(const Eigen::Vector2d& lower, const Eigen::Vector2d& lengths, bool periodic_x,
                           bool periodic_y) {
  Box box;
  box.lower << lower[0], lower[1], 0;
  box.lengths << lengths[0], lengths[1], 0;
  box.periodic = {periodic_x, periodic_y, false};
  return box;
}

}  // namespace cmp::neighbours
