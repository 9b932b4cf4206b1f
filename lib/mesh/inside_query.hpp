#pragma once
// Is a point inside a closed triangle mesh, asked for many points: the signed crossings of a
// ray from p with the faces (+1 where the face's shadow on the plane across the ray runs
// counter-clockwise, -1 clockwise), found through a 2D grid of the shadows, so a query costs
// the few faces over p instead of all of them. For a closed, consistently outward-oriented mesh
// the count is the winding number: 1 inside, 0 outside. Where a crossing is too close to call
// (p's shadow within round-off of a shadow's edge or corner, or p within round-off of the
// face above it), the generalised winding number decides (point_in_mesh.hpp), so inside(p) is
// winding_number(p) > 1/2 at every point, at a fraction of its cost.
// A shadow edge's side is computed with the same operations, in opposite order, by the two
// faces that share it (IEEE products commute and a - b = -(b - a)), so a point is never in both
// or neither of two neighbouring shadows.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace cmp::mesh {

class InsideQuery {
 public:
  // The faces [face_begin, face_end) of F over the flat positions x (x0 y0 z0 x1 ...). x and F
  // are read again for the undecided points: they must outlive the query, unchanged.
  InsideQuery(const double* x, const FaceMatrix& F, Eigen::Index face_begin, Eigen::Index face_end);

  bool inside(const Eigen::Vector3d& p) const;
  // How many queries so far the winding number answered (one query object per thread).
  long undecided() const { return undecided_; }

 private:
  const double* x_;
  const FaceMatrix& F_;
  Eigen::Index begin_, end_;
  std::vector<double> corners_;  // per face: x, y, z of its three corners
  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0, cell_ = 1, side_tolerance_ = 0, height_tolerance_ = 0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> cell_start_, cell_faces_;  // faces whose shadow's bounding box meets each cell (CSR)
  mutable long undecided_ = 0;
};

}  // namespace cmp::mesh
