#include "mesh/dual_areas.hpp"

#include "mesh/face_areas.hpp"

namespace cmp::mesh {

Eigen::VectorXd vertex_dual_areas(const VertexMatrix& V, const FaceMatrix& F) {
  const Eigen::VectorXd areas = face_areas(V, F);
  Eigen::VectorXd dual = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) dual[F(f, k)] += areas[f] / 3;
  return dual;
}

}  // namespace cmp::mesh
