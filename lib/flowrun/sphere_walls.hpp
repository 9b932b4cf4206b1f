#pragma once
// The exact geometry of a sphere packing on a lattice of nodes: which nodes are fluid, and
// for a fluid node's link towards a solid node, where along the link the sphere surface lies
// (the wall distance of interpolated, Bouzidi-type, bounce-back). The voxel image percolate
// writes only says which nodes are solid, so the wall sits half-way along every cut link (a
// staircase); from the packing itself it sits where the sphere is.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace cmp::flowrun {

class SphereWalls {
 public:
  // Spheres (centres N x 3, radii N, in the box's length units) in the box [0, box), periodic
  // on the axes flagged (minimum image), on a lattice of nodes[a] nodes per axis whose node
  // (x, y, z) sits at ((x + 1/2) h_x, (y + 1/2) h_y, (z + 1/2) h_z), h = box / nodes (the
  // voxel centres of percolate's image when the lattice is not refined). Throws
  // std::invalid_argument for a non-positive box or radius, sizes that differ, nodes < 1.
  SphereWalls(const Eigen::Vector3d& box, std::array<bool, 3> periodic, const Eigen::MatrixX3d& centres,
              const Eigen::VectorXd& radii, std::array<int, 3> nodes);

  // 1 for a node outside every sphere (strictly farther than its radius from every centre),
  // 0 inside one; nodes product bytes, x fastest. Cost: the nodes inside the spheres' bounding
  // boxes, in parallel over spheres' z planes (no races: a node is only ever cleared).
  std::vector<std::uint8_t> fluid_mask() const;

  // For the link from node (x, y, z) along the integer lattice vector c (|c_a| <= 1): the
  // fraction q of the link, from the node, at which it first enters a sphere, q in (0, 1];
  // the smallest over all spheres. 0.5 (the half-way wall) when the link meets no sphere
  // (its far node was made solid for another reason, e.g. a dropped pocket) or when the node
  // itself lies inside a sphere. Cost: O(spheres) per call; links are asked once each.
  double wall_fraction(int x, int y, int z, const std::array<int, 3>& c) const;

  const Eigen::Vector3d& node_spacing() const { return h_; }

 private:
  // d along axis, reduced to its nearest periodic image when the axis is periodic.
  double minimum_image_if(double d, int axis) const;
  Eigen::Vector3d box_, h_;
  std::array<bool, 3> periodic_;
  Eigen::MatrixX3d centres_;
  Eigen::VectorXd radii_;
  std::array<int, 3> nodes_;
};

}  // namespace cmp::flowrun
