#pragma once
// Radius of curvature estimated on every interior edge from the dihedral angle of its two
// triangles (thesis A.3.3).
#include "mesh/tri_mesh.hpp"
#include <Eigen/Core>

namespace cmp::mesh {

enum class CurvatureEstimator {
  // Eq. A.7 as printed: 1/R = 2 sin(theta/2) / h, h = (h1 + h2)/2 the mean altitude of the two
  // triangles onto the shared edge. On a smooth, fine mesh it overestimates R by a factor 3/2
  // (the centroids are (h1 + h2)/3 apart, not h): kept to reproduce Fig. A.5.
  ThesisA7,
  // The same angle over the distance between the two centroids across the edge:
  // 1/R = 2 sin(theta/2) / d, d = (h1 + h2)/3. Unbiased on fine, regular meshes.
  CentroidDistance,
};

// Estimated radius of curvature for every edge of EdgeTopology::edges (see edge_topology.hpp),
// in the same order. theta is the angle between the two face normals. Edges with fewer or more
// than two faces, and flat pairs (theta = 0), get +infinity.
//   V  #V by 3, F  #F by 3 consistently oriented
Eigen::VectorXd edge_curvature_radii(const VertexMatrix& V, const FaceMatrix& F,
                                     CurvatureEstimator estimator = CurvatureEstimator::ThesisA7);

}  // namespace cmp::mesh
