#pragma once
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// How to compute the volume enclosed by a closed triangle mesh (thesis A.3.2).
enum class VolumeMethod {
  // Sum of tetrahedra built on every triangle and the vertex centroid. Exact for a mesh that
  // is star-shaped about its centroid (e.g. convex); signed by orientation.
  CentroidTetrahedra,
  // Divergence theorem with F = (x, 0, 0): V = sum_t x_c(t) n_x(t) A_t, x_c the triangle's
  // centroid (the thesis's Eq. A.6 drops x_c; as printed it sums to zero). Exact for any
  // closed, consistently oriented, non-self-intersecting mesh, star-shaped or not.
  DivergenceTheorem,
};

// Signed enclosed volume: positive when faces are oriented outward.
//   V  #V by 3, F  #F by 3 closed triangle mesh
double enclosed_volume(const VertexMatrix& V, const FaceMatrix& F,
                       VolumeMethod method = VolumeMethod::DivergenceTheorem);

}  // namespace cmp::mesh
