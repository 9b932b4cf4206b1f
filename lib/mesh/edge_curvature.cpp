#include "mesh/edge_curvature.hpp"

#include "mesh/edge_topology.hpp"
#include "mesh/face_areas.hpp"
#include "mesh/face_normals.hpp"

#include <cmath>
#include <limits>

namespace cmp::mesh {

Eigen::VectorXd edge_curvature_radii(const VertexMatrix& V, const FaceMatrix& F,
                                     CurvatureEstimator estimator) {
  const EdgeTopology topology = edge_topology(F);
  const VertexMatrix normals = face_normals(V, F);
  const Eigen::VectorXd areas = face_areas(V, F);
  const Eigen::Index edge_count = topology.edges.rows();
  Eigen::VectorXd radii(edge_count);
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    const int f1 = topology.edge_faces(e, 0), f2 = topology.edge_faces(e, 1);
    radii[e] = std::numeric_limits<double>::infinity();
    if (topology.edge_face_counts[e] != 2) continue;
    const double length = (V.row(topology.edges(e, 0)) - V.row(topology.edges(e, 1))).norm();
    if (length <= 0) continue;
    // Angle between the normals from atan2 of |n1 x n2| and n1.n2: accurate for small angles,
    // where acos of the dot product loses half the digits.
    const Eigen::Vector3d n1 = normals.row(f1), n2 = normals.row(f2);
    const double theta = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
    const double two_sin = 2 * std::sin(theta / 2);
    if (two_sin <= 0) continue;
    const double h1 = 2 * areas[f1] / length, h2 = 2 * areas[f2] / length;
    const double arm = estimator == CurvatureEstimator::ThesisA7 ? (h1 + h2) / 2 : (h1 + h2) / 3;
    radii[e] = arm / two_sin;
  }
  return radii;
}

}  // namespace cmp::mesh
