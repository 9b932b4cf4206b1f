#pragma once
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// Makes the faces of every connected component consistently oriented (by flipping faces
// across edges traversed twice in the same direction, breadth-first from each component's
// first face) and then outward (each closed component's signed volume made positive). An open
// component (one with boundary edges) has no outside: it gets the orientation that flips the
// fewer of its faces. Components are connected through edges shared by two faces. O(#F log #F).
//   V  #V by 3
//   F  #F by 3, modified in place; a flip swaps columns 1 and 2
// Returns the number of faces flipped (0 for a mesh already oriented outward). Throws
// cmp::ComputationError if a component is not orientable (a Moebius strip) or not a manifold
// (an edge in more than two faces, a face that repeats a vertex), leaving F unchanged; throws
// std::out_of_range when an index of F is outside [0, #V).
long orient_outward(const VertexMatrix& V, FaceMatrix& F);

}  // namespace cmp::mesh
