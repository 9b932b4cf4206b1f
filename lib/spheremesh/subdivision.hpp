#pragma once
// Iterative sphere triangulations of thesis A.2.1: start from a polyhedron ("level 1") and
// subdivide every triangle once per level, projecting new nodes onto the sphere.
#include "mesh/tri_mesh.hpp"
#include <string>

namespace cmp::spheremesh {

enum class Subdivision {
  Simple,       // cube (12 triangles), bisection of each triangle's longest edge per level
  Tetrahedron,  // quadrisection per level
  Octahedron,
  Icosahedron,
};

// "simple", "tetra", "octa", "icosa"; throws cmp::UsageError for other names.
Subdivision subdivision_from_name(const std::string& name);
std::string subdivision_name(Subdivision scheme);

// The finest level (icosa at 14 is 1.3*10^9 triangles); the counts below are defined up to it.
inline constexpr int kMaxSubdivisionLevel = 14;

// Vertex and triangle counts at a level, from the closed forms (Simple: 6*2^(L-1)+2 nodes;
// quadrisection: T_1 4^(L-1) triangles, T/2 + 2 nodes). Throw cmp::UsageError for a level
// outside [1, kMaxSubdivisionLevel] (level 0 shifted by a negative count, undefined).
long subdivision_vertex_count(Subdivision scheme, int level);
long subdivision_face_count(Subdivision scheme, int level);

// The mesh at `level` (1 = the base polyhedron) on the sphere of `radius` centred at the
// origin. Triangles are flat (chordal), new nodes are chord midpoints projected radially
// after every level, faces oriented outward. The Simple cube's face diagonals all meet at the
// corners (1,1,1) and (-1,-1,-1): the only pattern that reproduces Table A.1.
// Throws cmp::UsageError for a level outside [1, kMaxSubdivisionLevel] or radius <= 0.
mesh::TriMesh subdivided_sphere(Subdivision scheme, int level, double radius = 1.0);

}  // namespace cmp::spheremesh
