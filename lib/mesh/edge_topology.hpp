#pragma once
#include "mesh/tri_mesh.hpp"
#include <vector>

namespace cmp::mesh {

// The undirected edges of a triangle mesh and the faces on each side.
struct EdgeTopology {
  EdgeMatrix edges;       // #E by 2, each edge once, edges(e,0) < edges(e,1), sorted lexicographically
  EdgeMatrix edge_faces;  // #E by 2, the first two faces containing edge e (-1 where fewer)
  std::vector<int> edge_face_counts;  // #E, how many faces contain edge e (2 on a closed manifold)
};

// Builds the edge list in O(#F log #F). The side of a degenerate face that joins a vertex to
// itself is not an edge and is left out; a face (a, a, b) puts both of its sides a-b on one edge.
//   F  #F by 3 triangle indices
EdgeTopology edge_topology(const FaceMatrix& F);

// True when face f has the directed side u -> v in its corner order (so the face to the other
// side of a consistently oriented edge has v -> u).
inline bool face_has_side(const FaceMatrix& F, Eigen::Index f, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) == u && F(f, (k + 1) % 3) == v) return true;
  return false;
}

// Vertex-vertex adjacency in compressed-row form: the neighbours of vertex i are
// neighbours[offsets[i] .. offsets[i+1]), sorted ascending, each once.
struct VertexAdjacency {
  std::vector<int> offsets;     // #V + 1
  std::vector<int> neighbours;  // 2 #E
};

//   F  #F by 3, vertex_count  #V (vertices in no face get no neighbours)
// Throws std::out_of_range when an index of F is outside [0, vertex_count).
VertexAdjacency vertex_adjacency(const FaceMatrix& F, int vertex_count);

}  // namespace cmp::mesh
