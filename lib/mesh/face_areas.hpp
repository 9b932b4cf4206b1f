#pragma once
#include "mesh/tri_mesh.hpp"
#include <Eigen/Core>

namespace cmp::mesh {

// Area of every (flat) triangle.
//   V  #V by 3, F  #F by 3
// Returns #F non-negative areas.
Eigen::VectorXd face_areas(const VertexMatrix& V, const FaceMatrix& F);

// Sum of face_areas(V, F).
double total_area(const VertexMatrix& V, const FaceMatrix& F);

}  // namespace cmp::mesh
