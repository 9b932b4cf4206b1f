#pragma once
// Is a point inside a closed triangle mesh? The generalised winding number (Jacobson et al.,
// SIGGRAPH 2013): w(p) = (1/4 pi) sum over the faces of the solid angle each subtends at p
// (Van Oosterom and Strackee's formula), exactly 1 inside and 0 outside a closed,
// consistently outward-oriented mesh, whatever its shape, and robust near the surface (it
// changes by 1 only across it). O(#F) per point, no set-up, nothing allocated.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

namespace cmp::mesh {

// The winding number of the faces F (rows of V) around p; the faces may be any subset of a
// larger mesh (one shell of a packing). V's rows are points; p in the same frame.
double winding_number(const VertexMatrix& V, const FaceMatrix& F, const Eigen::Vector3d& p);

// Same with the vertex positions in a flat state vector (x0 y0 z0 x1 ...) and the faces given
// as rows [face_begin, face_end) of F.
double winding_number(const double* x, const FaceMatrix& F, Eigen::Index face_begin, Eigen::Index face_end,
                      const Eigen::Vector3d& p);

// winding_number > 1/2.
inline bool inside_closed_mesh(const VertexMatrix& V, const FaceMatrix& F, const Eigen::Vector3d& p) {
  return winding_number(V, F, p) > 0.5;
}

}  // namespace cmp::mesh
