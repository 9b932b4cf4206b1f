#pragma once
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// Makes the faces of every connected component consistently oriented (by flipping faces
// across edges traversed twice in the same direction, breadth-first from each component's
// first face) and then outward (each closed component's signed volume made positive).
//   V  #V by 3
//   F  #F by 3, modified in place
// Returns the number of faces flipped. Throws cmp::ComputationError if a component is not
// orientable or not a manifold (an edge in more than two faces).
long orient_outward(const VertexMatrix& V, FaceMatrix& F);

}  // namespace cmp::mesh
