#pragma once
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// How to compute the volume enclosed by a closed triangle mesh (thesis A.3.2).
enum class VolumeMethod {
  // Sum of the signed tetrahedra (o, a, b, c), (1/6) (a-o).((b-o) x (c-o)), over every triangle
  // (a, b, c), with o the centroid of the face corners. The signs make it exact for any closed,
  // consistently oriented mesh, star-shaped about o or not (the torus is tested): tetrahedra
  // that stick out of the body cancel against negative ones.
  CentroidTetrahedra,
  // Divergence theorem with F = (x, 0, 0): V = sum_t x_c(t) n_x(t) A_t, x_c the triangle's
  // centroid (the thesis's Eq. A.6 drops x_c; as printed it sums to zero). Exact for any
  // closed, consistently oriented, non-self-intersecting mesh, star-shaped or not. Evaluated
  // as (1/6) sum (a+b+c-3o)_x ((b-a) x (c-a))_x with the same o.
  DivergenceTheorem,
};

// Signed enclosed volume: positive when faces are oriented outward.
//   V  #V by 3, F  #F by 3 closed triangle mesh
// Both methods agree to round-off on a closed mesh (they are the same exact polyhedral volume)
// and are translation invariant, also numerically: coordinates are taken relative to o, so a
// mesh 1e6 away from the origin keeps its digits. Flipping every face negates the result. On
// an open mesh neither is a volume (they differ from each other and depend on o). O(#F).
double enclosed_volume(const VertexMatrix& V, const FaceMatrix& F,
                       VolumeMethod method = VolumeMethod::DivergenceTheorem);

}  // namespace cmp::mesh
