#pragma once
// Exact test of a triangle against an axis-aligned box (the separating-axis theorem with the
// 13 axes of Akenine-Moeller, "Fast 3D triangle-box overlap testing", 2001).
#include <Eigen/Core>

namespace cmp::voxel {

// True when the closed triangle (a, b, c) and the closed box centre +- half overlap.
//   a, b, c   triangle corners; centre  box centre; half  3 positive half sides
// Touching counts as overlap (the test is conservative: a triangle lying exactly on a voxel
// face marks both voxels). Degenerate triangles (segments, points) are handled.
bool triangle_box_overlap(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                          const Eigen::Vector3d& centre, const Eigen::Vector3d& half);

}  // namespace cmp::voxel
