#include "mesh/face_normals.hpp"

#include <Eigen/Geometry>

namespace cmp::mesh {

VertexMatrix face_normals(const VertexMatrix& V, const FaceMatrix& F) {
  VertexMatrix normals(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0));
    const Eigen::RowVector3d n = (V.row(F(f, 1)) - a).cross(V.row(F(f, 2)) - a);
    const double length = n.norm();
    normals.row(f) = length > 0 ? Eigen::RowVector3d(n / length) : Eigen::RowVector3d::Zero();
  }
  return normals;
}

}  // namespace cmp::mesh
