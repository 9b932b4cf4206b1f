#pragma once
#include "mesh/tri_mesh.hpp"
#include <Eigen/Core>

namespace cmp::mesh {

// Barycentric dual area of every vertex, thesis Eq. A.1: C_i = (1/3) sum of the areas of the
// triangles that contain vertex i. Sums to the total area. A vertex in no triangle gets 0.
//   V  #V by 3, F  #F by 3
// Returns #V areas.
Eigen::VectorXd vertex_dual_areas(const VertexMatrix& V, const FaceMatrix& F);

}  // namespace cmp::mesh
