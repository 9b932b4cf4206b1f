#include "mesh/face_areas.hpp"

#include <Eigen/Geometry>

namespace cmp::mesh {

namespace {
// Half the norm of (b - a) x (c - a): the edge vectors are differences of nearby points, so a
// mesh far from the origin loses no more digits than one near it.
double triangle_area(const VertexMatrix& V, const FaceMatrix& F, Eigen::Index f) {
  const Eigen::RowVector3d a = V.row(F(f, 0));
  const Eigen::RowVector3d ab = V.row(F(f, 1)) - a, ac = V.row(F(f, 2)) - a;
  return 0.5 * ab.cross(ac).norm();
}
}  // namespace

Eigen::VectorXd face_areas(const VertexMatrix& V, const FaceMatrix& F) {
  Eigen::VectorXd areas(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) areas[f] = triangle_area(V, F, f);
  return areas;
}

double total_area(const VertexMatrix& V, const FaceMatrix& F) {
  double sum = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) sum += triangle_area(V, F, f);
  return sum;
}

}  // namespace cmp::mesh
