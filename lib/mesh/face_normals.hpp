#pragma once
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// Unit normal of every triangle, (b - a) x (c - a) normalised: outward for a closed mesh
// oriented counter-clockwise seen from outside. A degenerate (zero-area) triangle gets (0,0,0).
//   V  #V by 3, F  #F by 3
// Returns #F by 3 (row-major).
VertexMatrix face_normals(const VertexMatrix& V, const FaceMatrix& F);

}  // namespace cmp::mesh
