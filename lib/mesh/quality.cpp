#include "mesh/quality.hpp"

#include "mesh/dual_areas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmp::mesh {

namespace {
struct Sides {
  double a, b, c;  // a opposite corner 0, b opposite corner 1, c opposite corner 2
};
Sides sides(const VertexMatrix& V, const FaceMatrix& F, Eigen::Index f) {
  const auto p0 = V.row(F(f, 0)), p1 = V.row(F(f, 1)), p2 = V.row(F(f, 2));
  return {(p1 - p2).norm(), (p2 - p0).norm(), (p0 - p1).norm()};
}
double radius_ratio(const Sides& s) {
  const double abc = s.a * s.b * s.c;
  if (abc <= 0) return 0;
  return std::max(0.0, (s.b + s.c - s.a) * (s.c + s.a - s.b) * (s.a + s.b - s.c) / abc);
}
// Corner angle opposite side `opposite`, by the law of cosines with a clamp for round-off.
double corner_angle(double opposite, double u, double v) {
  if (u <= 0 || v <= 0) return 0;
  const double c = (u * u + v * v - opposite * opposite) / (2 * u * v);
  return std::acos(std::clamp(c, -1.0, 1.0));
}
}  // namespace

Eigen::VectorXd face_radius_ratios(const VertexMatrix& V, const FaceMatrix& F) {
  Eigen::VectorXd q(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) q[f] = radius_ratio(sides(V, F, f));
  return q;
}

Eigen::MatrixX3d face_angles(const VertexMatrix& V, const FaceMatrix& F) {
  Eigen::MatrixX3d angles(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Sides s = sides(V, F, f);
    angles(f, 0) = corner_angle(s.a, s.b, s.c);
    angles(f, 1) = corner_angle(s.b, s.c, s.a);
    angles(f, 2) = corner_angle(s.c, s.a, s.b);
  }
  return angles;
}

MeshQuality mesh_quality(const VertexMatrix& V, const FaceMatrix& F) {
  MeshQuality q;
  const Eigen::VectorXd dual = vertex_dual_areas(V, F);
  std::vector<char> used(V.rows(), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[F(f, k)] = 1;
  q.dual_area_min = std::numeric_limits<double>::infinity();
  q.dual_area_max = 0;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (used[i]) {
      q.dual_area_min = std::min(q.dual_area_min, dual[i]);
      q.dual_area_max = std::max(q.dual_area_max, dual[i]);
    }
  q.q_area = q.dual_area_max > 0 ? q.dual_area_min / q.dual_area_max : 0;

  const Eigen::VectorXd ratios = face_radius_ratios(V, F);
  const Eigen::MatrixX3d angles = face_angles(V, F);
  q.q_radius_ratio = ratios.size() ? ratios.minCoeff() : 0;
  q.radius_ratio_mean = ratios.size() ? ratios.mean() : 0;
  q.low_quality_fraction = ratios.size() ? (ratios.array() < 0.5).cast<double>().mean() : 0;
  q.angle_min = angles.size() ? angles.minCoeff() : 0;
  q.angle_max = angles.size() ? angles.maxCoeff() : 0;
  q.q_angle = q.angle_min / (M_PI / 3);
  return q;
}

}  // namespace cmp::mesh
