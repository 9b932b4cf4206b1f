#pragma once
// A flat triangulated disc for the clamped-plate benchmarks (thesis B.5.3-B.5.4, Figs. B.5-B.7:
// N ~ 1000-1200 vertices, triangles of edge a ~ 0.2-0.3 on R0 ~ 2.1-2.3): a hexagonal
// (equilateral-triangle) lattice of spacing a centred on the origin, clipped to r < R - 0.6 a,
// plus a ring of round(2 pi R/a) vertices on the circle r = R, Delaunay-triangulated and lightly
// smoothed next to the rim (Laplacian moves of the lattice vertices within 2 a of it).
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::mesh {

struct DiscMesh {
  TriMesh mesh;           // vertices in the plane z = 0; faces counter-clockwise seen from +z (normals +z)
  std::vector<int> rim;   // the vertices on the circle r = R, by increasing polar angle (the clamped edge)
  int centre = 0;         // the vertex at the origin (the point-load vertex)
  double spacing = 0;     // the lattice spacing a actually used
};

// A disc of radius R > 0 with about `vertices` vertices (>= 19; within a few percent): the
// spacing a is chosen so the count comes closest. Throws std::invalid_argument for bad values.
DiscMesh disc_mesh(double radius, long vertices);

// The same with a given spacing a (0 < a <= R/2).
DiscMesh disc_mesh_with_spacing(double radius, double spacing);

}  // namespace cmp::mesh
