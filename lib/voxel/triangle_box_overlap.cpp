#include "voxel/triangle_box_overlap.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cmp::voxel {

namespace {
// Does the axis separate the triangle's projection from the box's? (Axes of zero length, from
// parallel edges, never separate.)
bool separated(const Eigen::Vector3d& axis, const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
               const Eigen::Vector3d& v2, const Eigen::Vector3d& half) {
  const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
  const double r = half[0] * std::abs(axis[0]) + half[1] * std::abs(axis[1]) + half[2] * std::abs(axis[2]);
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}
}  // namespace

bool triangle_box_overlap(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                          const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  const Eigen::Vector3d v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // 1. the box's face normals: the triangle's bounding box against the box
  for (int k = 0; k < 3; ++k)
    if (std::min({v0[k], v1[k], v2[k]}) > half[k] || std::max({v0[k], v1[k], v2[k]}) < -half[k]) return false;
  // 2. the triangle's normal
  const Eigen::Vector3d e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
  const Eigen::Vector3d n = e0.cross(e1);
  if (separated(n, v0, v1, v2, half)) return false;
  // 3. the nine cross products of the box axes with the edges
  for (const Eigen::Vector3d* e : {&e0, &e1, &e2})
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      axis[k] = 1;
      if (separated(axis.cross(*e), v0, v1, v2, half)) return false;
    }
  return true;
}

}  // namespace cmp::voxel
