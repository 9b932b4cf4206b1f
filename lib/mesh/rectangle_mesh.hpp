#pragma once
// A flat rectangular sheet for the Poisson-ratio benchmark (thesis B.5.2, Fig. B.4B: L = 2.28,
// N ~ 2200): rows of vertices along x, stacked in y, alternate rows offset by half a spacing
// (a hexagonal lattice of nearly equilateral triangles), with an extra vertex closing each
// offset row on x = 0 and x = W so that the left and right edges are straight. Row spacing is
// H/(rows - 1), the number of rows chosen to make it as close to a sqrt(3)/2 as possible.
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::mesh {

struct RectangleMesh {
  TriMesh mesh;              // vertices in z = 0 filling [0, W] x [0, H]; faces counter-clockwise seen from +z
  std::vector<int> left;     // vertices on x = 0, by increasing y
  std::vector<int> right;    // vertices on x = W, by increasing y
  std::vector<int> bottom;   // vertices on y = 0, by increasing x
  std::vector<int> top;      // vertices on y = H, by increasing x
  double spacing = 0;        // the spacing a along the rows
};

// A W x H sheet (W, H > 0) with about `vertices` vertices (>= 9): the spacing a is chosen so the
// count comes closest. Throws std::invalid_argument for bad values.
RectangleMesh rectangle_mesh(double width, double height, long vertices);

// The same with a given row spacing a (0 < a <= min(W, H)/2).
RectangleMesh rectangle_mesh_with_spacing(double width, double height, double spacing);

}  // namespace cmp::mesh
