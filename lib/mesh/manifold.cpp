#include "mesh/manifold.hpp"

#include "mesh/edge_topology.hpp"

#include <sstream>
#include <stdexcept>

namespace cmp::mesh {

namespace {
long used_vertex_count(const FaceMatrix& F, int vertex_count) {
  std::vector<char> used(static_cast<std::size_t>(vertex_count), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(F(f, k))] = 1;
  long count = 0;
  for (char u : used) count += u;
  return count;
}

void check_indices(const FaceMatrix& F, int vertex_count, const char* who) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= vertex_count))
    throw std::out_of_range(std::string(who) + ": a face index is outside [0, " + std::to_string(vertex_count) + ")");
}
}  // namespace

std::string ManifoldReport::describe() const {
  std::ostringstream s;
  s << vertices << " vertices, " << edges << " edges, " << faces << " faces, Euler characteristic "
    << euler_characteristic << "; " << unused_vertices << " unused vertices, " << boundary_edges
    << " boundary edges, " << nonmanifold_edges << " non-manifold edges, " << degenerate_faces
    << " degenerate faces, " << misoriented_edges << " misoriented edges";
  return s.str();
}

ManifoldReport manifold_report(const FaceMatrix& F, int vertex_count) {
  check_indices(F, vertex_count, "manifold_report");
  const EdgeTopology t = edge_topology(F);
  ManifoldReport r;
  r.vertices = vertex_count;
  r.edges = t.edges.rows();
  r.faces = F.rows();
  const long used = used_vertex_count(F, vertex_count);
  r.unused_vertices = vertex_count - used;
  r.euler_characteristic = used - r.edges + r.faces;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0)) ++r.degenerate_faces;
  for (Eigen::Index e = 0; e < t.edges.rows(); ++e) {
    const int count = t.edge_face_counts[static_cast<std::size_t>(e)];
    if (count == 1) ++r.boundary_edges;
    if (count > 2) ++r.nonmanifold_edges;
    if (count != 2) continue;
    const int u = t.edges(e, 0), v = t.edges(e, 1);
    if (t.edge_faces(e, 0) == t.edge_faces(e, 1)) continue;  // both sides of one degenerate face
    if (face_has_side(F, t.edge_faces(e, 0), u, v) == face_has_side(F, t.edge_faces(e, 1), u, v)) ++r.misoriented_edges;
  }
  return r;
}

long euler_characteristic(const FaceMatrix& F, int vertex_count) {
  check_indices(F, vertex_count, "euler_characteristic");
  return used_vertex_count(F, vertex_count) - edge_topology(F).edges.rows() + F.rows();
}

}  // namespace cmp::mesh
