#pragma once
// Delaunay triangulation of points on a sphere: the topology step of A.2.2 (the thesis used
// STRIPACK's Algorithm 772; this is CGAL's Delaunay_triangulation_on_sphere_2, exact predicates).
#include "mesh/tri_mesh.hpp"

namespace cmp::spheremesh {

// Triangulates points lying on a sphere centred at the origin (each is projected radially for
// the predicates; the coordinates themselves are not changed).
//   points  #N by 3, N >= 4, not all on one great circle, no two coincident
// Returns #F = 2N - 4 triangles indexing `points`, oriented outward. Throws
// cmp::ComputationError when some point could not be inserted (coincident or too close
// points) or the points do not span the sphere.
mesh::FaceMatrix spherical_delaunay(const mesh::VertexMatrix& points);

}  // namespace cmp::spheremesh
