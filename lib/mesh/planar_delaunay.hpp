#pragma once
// Delaunay triangulation of points in a plane (the flat benchmark meshes of lib/mesh).
#include "mesh/tri_mesh.hpp"

namespace cmp::mesh {

// Delaunay triangulation of the points' x and y coordinates (#P by 3, z ignored), #P >= 3,
// faces counter-clockwise seen from +z, covering the convex hull. Bowyer-Watson with a naive
// search, O(#P x #F): meant for the few thousand points of a benchmark mesh. Floating-point
// predicates: points in general position up to cocircular sets (any of the equivalent
// triangulations is returned). Throws std::invalid_argument for fewer than 3 points, duplicate
// points or all points collinear.
FaceMatrix planar_delaunay(const VertexMatrix& P);

}  // namespace cmp::mesh
