#pragma once
#include "mesh/tri_mesh.hpp"
#include <string>

namespace cmp::mesh {

// Topological health of a triangle mesh.
struct ManifoldReport {
  long vertices = 0, edges = 0, faces = 0;
  long euler_characteristic = 0;   // V - E + F (2 for a sphere), counting only used vertices
  long unused_vertices = 0;        // vertices in no face
  long boundary_edges = 0;         // edges with one face
  long nonmanifold_edges = 0;      // edges with more than two faces
  long degenerate_faces = 0;       // faces that repeat a vertex index
  long misoriented_edges = 0;      // interior edges traversed in the same direction by both faces
  bool closed_manifold() const {   // every edge in exactly two faces, no repeated indices
    return boundary_edges == 0 && nonmanifold_edges == 0 && degenerate_faces == 0;
  }
  bool consistently_oriented() const { return misoriented_edges == 0; }
  std::string describe() const;    // one line, for error messages
};

// O(#F log #F).
//   F  #F by 3, vertex_count  #V
// Throws std::out_of_range when an index of F is outside [0, vertex_count).
ManifoldReport manifold_report(const FaceMatrix& F, int vertex_count);

// V - E + F over the vertices used by F.
long euler_characteristic(const FaceMatrix& F, int vertex_count);

}  // namespace cmp::mesh
