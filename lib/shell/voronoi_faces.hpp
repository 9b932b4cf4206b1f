#pragma once
// Facets of the periodic Voronoi cells of points in a cube (the Statistical Honeycomb
// comparison of thesis Ch. 4: about 13.6 faces per cell near confluence, against the contact
// number Z). CGAL's periodic 3D Delaunay triangulation, which needs a cubic domain; with few
// points it works on its 27-sheeted cover, which this handles.
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

// The number of facets of the Voronoi cell of every point of P (#N by 3, any coordinates:
// wrapped into [0, side)^3) in the periodic cube of the given side. A Delaunay edge whose dual
// facet has no area (points on a common sphere, as in simple cubic or FCC lattices, where
// the triangulation's choice of diagonal is arbitrary) is not a facet: facets of area below
// 1e-9 (side^3/N)^(2/3) are dropped. Throws cmp::UsageError for side <= 0 or two points at
// the same place.
std::vector<int> periodic_voronoi_face_counts(const mesh::VertexMatrix& P, double side);

}  // namespace cmp::shell
