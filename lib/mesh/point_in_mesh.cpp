#include "mesh/point_in_mesh.hpp"

#include <cmath>
#include <numbers>

namespace cmp::mesh {

double winding_number(const double* x, const FaceMatrix& F, Eigen::Index face_begin, Eigen::Index face_end,
                      const Eigen::Vector3d& p) {
  double sum = 0;
  for (Eigen::Index f = face_begin; f < face_end; ++f) {
    const Eigen::Vector3d a = Eigen::Map<const Eigen::Vector3d>(x + 3 * F(f, 0)) - p;
    const Eigen::Vector3d b = Eigen::Map<const Eigen::Vector3d>(x + 3 * F(f, 1)) - p;
    const Eigen::Vector3d c = Eigen::Map<const Eigen::Vector3d>(x + 3 * F(f, 2)) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2.0 * std::atan2(numerator, denominator);
  }
  return sum / (4.0 * std::numbers::pi);
}

double winding_number(const VertexMatrix& V, const FaceMatrix& F, const Eigen::Vector3d& p) {
  return winding_number(V.data(), F, 0, F.rows(), p);
}

}  // namespace cmp::mesh
