#include "mesh/enclosed_volume.hpp"

#include <Eigen/Geometry>

namespace cmp::mesh {

namespace {
// Both methods work on coordinates relative to o, the centroid of the face corners (so that
// vertices in no face do not move it). For a closed mesh the
// result does not depend on o in exact arithmetic, but a mesh far from the origin would
// otherwise lose digits: with |x| ~ 1e6 and edges ~ 1, each term of a.(b x c) is ~1e12 while
// the sum is ~1, and the cancellation leaves nothing.

// Six times the signed volume of the tetrahedron (o, a, b, c).
double tetrahedron6(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, const Eigen::RowVector3d& c) {
  return a.dot(b.cross(c));
}

// Six times x_c n_x A_t: 3 x_c is the sum of the x coordinates of the corners, and 2 n A_t is
// (b - a) x (c - a), computed from edge vectors (independent of o).
double divergence6(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, const Eigen::RowVector3d& c) {
  const Eigen::RowVector3d ab = b - a, ac = c - a;
  const double twice_area_nx = ab[1] * ac[2] - ab[2] * ac[1];
  return (a[0] + b[0] + c[0]) * twice_area_nx;
}
}  // namespace

double enclosed_volume(const VertexMatrix& V, const FaceMatrix& F, VolumeMethod method) {
  if (F.rows() == 0) return 0;
  Eigen::RowVector3d o = Eigen::RowVector3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) o += V.row(F(f, k));
  o /= static_cast<double>(3 * F.rows());
  double sum = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)) - o, b = V.row(F(f, 1)) - o, c = V.row(F(f, 2)) - o;
    sum += method == VolumeMethod::CentroidTetrahedra ? tetrahedron6(a, b, c) : divergence6(a, b, c);
  }
  return sum / 6;
}

}  // namespace cmp::mesh
