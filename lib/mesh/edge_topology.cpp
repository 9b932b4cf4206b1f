#include "mesh/edge_topology.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace cmp::mesh {

EdgeTopology edge_topology(const FaceMatrix& F) {
  // Every face side as (low vertex, high vertex, face), sorted: the sides of one edge become
  // adjacent, in increasing face order. Sides that join a vertex to itself (degenerate faces)
  // are not edges and are left out.
  std::vector<std::array<int, 3>> sides;
  sides.reserve(static_cast<std::size_t>(F.rows()) * 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      if (a != b) sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
    }
  std::sort(sides.begin(), sides.end());

  std::size_t edge_count = 0;
  for (std::size_t s = 0; s < sides.size(); ++s)
    if (s == 0 || sides[s][0] != sides[s - 1][0] || sides[s][1] != sides[s - 1][1]) ++edge_count;

  EdgeTopology t;
  t.edges.resize(static_cast<Eigen::Index>(edge_count), 2);
  t.edge_faces.setConstant(static_cast<Eigen::Index>(edge_count), 2, -1);
  t.edge_face_counts.assign(edge_count, 0);
  Eigen::Index e = -1;
  for (std::size_t s = 0; s < sides.size(); ++s) {
    if (s == 0 || sides[s][0] != sides[s - 1][0] || sides[s][1] != sides[s - 1][1]) {
      ++e;
      t.edges(e, 0) = sides[s][0];
      t.edges(e, 1) = sides[s][1];
    }
    int& count = t.edge_face_counts[static_cast<std::size_t>(e)];
    if (count < 2) t.edge_faces(e, count) = sides[s][2];
    ++count;
  }
  return t;
}

VertexAdjacency vertex_adjacency(const FaceMatrix& F, int vertex_count) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= vertex_count))
    throw std::out_of_range("vertex_adjacency: a face index is outside [0, " + std::to_string(vertex_count) + ")");
  const EdgeTopology t = edge_topology(F);
  VertexAdjacency a;
  a.offsets.assign(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (Eigen::Index e = 0; e < t.edges.rows(); ++e) {
    ++a.offsets[static_cast<std::size_t>(t.edges(e, 0)) + 1];
    ++a.offsets[static_cast<std::size_t>(t.edges(e, 1)) + 1];
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(vertex_count); ++i) a.offsets[i + 1] += a.offsets[i];
  a.neighbours.resize(static_cast<std::size_t>(a.offsets.back()));
  // Edges come sorted by (low, high): vertex v first receives its lower neighbours (from the
  // edges (u, v), u < v, in increasing u), then its higher ones (from (v, w), in increasing w),
  // so every row comes out sorted without a sort.
  std::vector<int> next(a.offsets.begin(), a.offsets.end() - 1);
  for (Eigen::Index e = 0; e < t.edges.rows(); ++e) {
    const int u = t.edges(e, 0), v = t.edges(e, 1);
    a.neighbours[static_cast<std::size_t>(next[u]++)] = v;
    a.neighbours[static_cast<std::size_t>(next[v]++)] = u;
  }
  return a;
}

}  // namespace cmp::mesh
