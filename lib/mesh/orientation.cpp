#include "mesh/orientation.hpp"

#include "core/errors.hpp"
#include "mesh/edge_topology.hpp"
#include "mesh/enclosed_volume.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace cmp::mesh {

namespace {
std::string edge_name(int u, int v) { return "(" + std::to_string(u) + ", " + std::to_string(v) + ")"; }

// Up to three neighbours of every face across its interior edges, with the shared edge.
struct FaceNeighbour {
  int face = -1, u = -1, v = -1;
};
using FaceNeighbours = std::vector<std::array<FaceNeighbour, 3>>;

FaceNeighbours face_neighbours(const FaceMatrix& F, const EdgeTopology& t) {
  FaceNeighbours adjacent(static_cast<std::size_t>(F.rows()));
  std::vector<int> filled(static_cast<std::size_t>(F.rows()), 0);
  for (Eigen::Index e = 0; e < t.edges.rows(); ++e) {
    const int count = t.edge_face_counts[static_cast<std::size_t>(e)];
    const int u = t.edges(e, 0), v = t.edges(e, 1);
    if (count > 2)
      throw ComputationError("orient_outward: not a manifold: edge " + edge_name(u, v) + " is in " +
                             std::to_string(count) + " faces");
    if (count != 2) continue;
    const int f = t.edge_faces(e, 0), g = t.edge_faces(e, 1);
    adjacent[static_cast<std::size_t>(f)][static_cast<std::size_t>(filled[f]++)] = {g, u, v};
    adjacent[static_cast<std::size_t>(g)][static_cast<std::size_t>(filled[g]++)] = {f, u, v};
  }
  return adjacent;
}
}  // namespace

long orient_outward(const VertexMatrix& V, FaceMatrix& F) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
    throw std::out_of_range("orient_outward: a face index is outside [0, " + std::to_string(V.rows()) + ")");
  const int face_count = static_cast<int>(F.rows());
  for (int f = 0; f < face_count; ++f)
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0))
      throw ComputationError("orient_outward: face " + std::to_string(f) + " repeats a vertex");
  const EdgeTopology t = edge_topology(F);
  const FaceNeighbours adjacent = face_neighbours(F, t);

  // Breadth-first over each component: a neighbour must traverse the shared edge opposite to
  // the (possibly flipped) current face; flip it if it does not. A face reached again with the
  // wrong orientation closes an odd cycle of flips: the component is not orientable.
  std::vector<char> flip(static_cast<std::size_t>(face_count), 0);
  std::vector<int> component(static_cast<std::size_t>(face_count), -1);
  std::vector<std::vector<int>> members;
  std::vector<int> queue;
  for (int seed = 0; seed < face_count; ++seed) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    component[seed] = id;
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      members[id].push_back(f);
      for (const FaceNeighbour& n : adjacent[static_cast<std::size_t>(f)]) {
        if (n.face < 0) break;
        const bool f_forward = face_has_side(F, f, n.u, n.v) != static_cast<bool>(flip[f]);
        const bool g_forward_now = face_has_side(F, n.face, n.u, n.v);
        if (component[n.face] < 0) {
          component[n.face] = id;
          flip[n.face] = g_forward_now == f_forward;
          queue.push_back(n.face);
        } else if ((g_forward_now != static_cast<bool>(flip[n.face])) == f_forward) {
          throw ComputationError("orient_outward: not orientable (e.g. a Moebius strip): the component of face " +
                                 std::to_string(seed) + " cannot be oriented consistently across edge " +
                                 edge_name(n.u, n.v));
        }
      }
    }
  }

  // Each component's overall orientation: outward (positive volume) when closed, else the one
  // that keeps most of the input's faces as they were.
  std::vector<char> open(members.size(), 0);
  for (Eigen::Index e = 0; e < t.edges.rows(); ++e)
    if (t.edge_face_counts[static_cast<std::size_t>(e)] == 1) open[component[t.edge_faces(e, 0)]] = 1;
  for (std::size_t id = 0; id < members.size(); ++id) {
    const std::vector<int>& faces = members[id];
    bool reverse = false;
    if (open[id]) {
      long flipped = 0;
      for (int f : faces) flipped += flip[f];
      reverse = 2 * flipped > static_cast<long>(faces.size());
    } else {
      FaceMatrix oriented(static_cast<Eigen::Index>(faces.size()), 3);
      for (std::size_t k = 0; k < faces.size(); ++k) {
        const int f = faces[k];
        oriented.row(static_cast<Eigen::Index>(k)) = F.row(f);
        if (flip[f]) std::swap(oriented(static_cast<Eigen::Index>(k), 1), oriented(static_cast<Eigen::Index>(k), 2));
      }
      reverse = enclosed_volume(V, oriented) < 0;
    }
    if (reverse)
      for (int f : faces) flip[f] = !flip[f];
  }

  long flipped = 0;
  for (int f = 0; f < face_count; ++f)
    if (flip[f]) {
      std::swap(F(f, 1), F(f, 2));
      ++flipped;
    }
  return flipped;
}

}  // namespace cmp::mesh
