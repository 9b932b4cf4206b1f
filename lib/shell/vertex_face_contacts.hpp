#pragma once
// Hertz contacts of shells through their surfaces ("hertz-faces"): every vertex p of a shell A
// is pushed out of a layer of thickness delta (the contact distance) around every other shell
// B's triangulated surface, by each of B's triangles T within delta of it:
//
//   d_T   = |p - q_T|, q_T the closest point of T to p (minimum image in a periodic box)
//   h     = delta - d_T > 0
//   U     = sum over T of (8/15) E* sqrt(R*) h^(5/2),   E* = E / (2 (1 - nu^2)) (as for vertex
//           spheres), R* = delta / 2 (a sphere of radius delta/2 on a plate: the plate's
//           curvature is the shell's, far below 1/delta)
//   force -U'(h) (p - q_T)/d_T on p per triangle, and its opposite on T's corners, split by
//           the barycentric weights of q_T: the exact gradient (q_T minimises the distance to
//           T, so its own motion drops out). Each d_T is C1 in the positions while p is off T,
//           so U is C1 everywhere.
// Every triangle counts, not only the closest one of each shell: in a valley of B's surface
// (a dimple, the groove between two flattened facets) the closest triangle jumps from one
// side to the other across the bisector, and a force taken from it alone jumps with it; the
// relaxation then chatters there and stalls. The price: over an edge (a corner) of B, where
// two (several) triangles share the closest point, the force is that many times the force over
// a face; the barrier is at least U(delta) at every point of the surface.
// Both ordered pairs count (A's vertices against B's faces and B's vertices against A's), so a
// vertex can no longer slip between another shell's vertex spheres, and delta can be the wall
// thickness t (two walls touching have their mid-surfaces t apart) instead of vertex spheres
// sized to the triangles.
//
// Candidates: for each vertex, the triangles that may come within delta of it, from a Verlet
// list held tight. Every point of a triangle lies within (its longest edge)/sqrt(3) of a
// corner, so a triangle within delta + skin of p has a corner within reach + skin, reach =
// delta + that (skin = kSkin reach): the broad phase pairs vertices of different shells that close
// (linked cells of lib/neighbours, one pass on one thread); the narrow phase, on all threads,
// keeps of the triangles around p's partners those truly within delta + skin of p. The list
// holds while no vertex has moved skin/2 since it was built (a triangle's distance to p
// changes by at most the largest move of p plus that of its corners) and the box has not
// changed; every evaluation then tests only triangles within a skin of contact. The box is
// the vertices' bounding box, or, once set_box() gave one, [0, L) with the minimum image along
// its periodic axes: the interface of ShellContactTerm, as VertexContacts, so a packing run can
// take either style. Vertices are handled in fixed chunks on all threads; energies are summed
// per chunk in chunk order, and the forces of a large system scattered in fixed slabs of
// chunks, one gradient each, added in slab order: the same bits for any thread count.
#include "shell/energy_term.hpp"
#include "shell/hertz_contacts.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace cmp::shell {

// Barycentric weights (w_a, w_b, w_c), each in [0, 1] and summing to 1, of the point of the
// triangle (a, b, c) closest to p (Voronoi regions of corners, edges and the interior, as in
// Ericson, "Real-Time Collision Detection" 5.1.5). A degenerate triangle gives a closest point
// on its edges.
inline Eigen::Vector3d closest_triangle_weights(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class VertexFaceContacts final : public ShellContactTerm {
 public:
  // Throws cmp::UsageError for bad parameters (contact_distance among them) or a face index
  // outside the mesh.
  VertexFaceContacts(const mesh::TriMesh& rest, const ContactParameters& p);
  std::string name() const override { return "hertz-faces"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return static_cast<long>(shell_of_.size()); }

  // The box [0, L), periodic along the flagged axes. Throws cmp::UsageError for a side that is
  // not positive and finite or a periodic side shorter than 4 delta. At each call, a periodic
  // side must also be at least 2 (1.5 (delta + L/sqrt 3) + L), L the longest edge (the Verlet
  // list's reach and a triangle's span; cmp::ComputationError otherwise).
  void set_box(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) override;
  void clear_box() override {
    box_.reset();
    list_valid_ = false;
  }
  const std::optional<BoxSides>& box() const override { return box_; }

  // Every contact (vertex i, a triangle of another shell within delta) at x, vertex by vertex
  // (ascending), triangles ascending: corners the triangle's, weights those of its point q
  // closest to x_i, d = x_i - q (minimum image), r = |d|, overlap = delta - r.
  std::vector<Touch> touches(std::span<const double> x) const override;
  // 1 for every vertex in a contact at x: the pushed vertex and the corners of the triangle
  // with a positive weight.
  std::vector<char> touching(std::span<const double> x) const override;
  const std::vector<int>& vertex_shells() const override { return shell_of_; }
  const std::vector<int>& face_shells() const { return face_shell_; }
  double contact_distance() const { return delta_; }
  double contact_reach() const override { return delta_; }

  // How many times the Verlet list of candidate triangles was built (a diagnostic).
  long list_builds() const { return list_builds_; }

  static constexpr long kChunkVertices = 2048;
  static constexpr int kBroadPhaseChunks = 16;  // chunks of cells of the list's broad phase

 private:
  struct Record {
    int i, face;
    double w[3], d[3], r;
  };
  // Fills records_ (one list per fixed chunk of vertices) with every contact at x.
  void collect(std::span<const double> x) const;

  std::vector<int> shell_of_, face_shell_, faces_;  // faces_: 3 corners per face
  std::vector<int> incident_start_, incident_;      // faces around each vertex (CSR)
  double delta_, estar_, rstar_;
  std::optional<BoxSides> box_;
  mutable mesh::VertexMatrix scratch_;
  // The Verlet list: candidate triangles per vertex (CSR, ascending), the positions it was
  // built at and the largest move it tolerates.
  void build_candidates(std::span<const double> x) const;
  bool candidates_hold(std::span<const double> x) const;
  bool parallel() const;
  // The fixed chunks of kChunkVertices vertices (at least one) that every per-vertex pass uses.
  static int vertex_chunks(long n) { return static_cast<int>(std::max<long>(1, (n + kChunkVertices - 1) / kChunkVertices)); }
  // The skin of the list, as a fraction of delta + (longest edge)/sqrt(3): thicker lists are
  // rebuilt less often, and their far candidates cost one bound each (collect() skips them).
  // One step at phi 0.93 of 50 x 2,562 shells (2,255 FIRE iterations, 2 threads): 0.12 92 s,
  // 0.2 81 s, 0.3 77 s, 0.45 86 s, 0.6 96 s; 16 x 642 shells (one thread's passes) the same
  // at 0.12 and 0.3.
  static constexpr double kSkin = 0.3;
  static constexpr int kStraddles = 27;  // image code of a candidate whose corners lie in different images
  mutable std::vector<int> candidate_start_, candidates_;
  mutable std::vector<std::uint8_t> candidate_images_;  // per candidate: its periodic image seen from the vertex
  mutable std::vector<double> candidate_gap_;  // per candidate: its distance from the vertex at the build
  mutable std::vector<double> moved_;          // per vertex: its move from the (scaled) reference
  mutable std::vector<double> face_moved_;     // per face: the largest move of its corners
  // A candidate is tested only while its bounded distance is below this times delta (a hair
  // above 1: round-off in the bound never skips a contact).
  static constexpr double kSkipMargin = 1.0 + 1e-9;
  mutable std::vector<double> reference_;
  mutable double tolerated_move_ = 0;
  mutable long list_builds_ = 0;
  mutable double skin_ = 0, list_scale_ = 1;  // the list's skin, and the box's scale since it was built
  double tolerated_move(double scale) const;  // the largest move of a vertex from the reference
  mutable bool list_valid_ = false;
  mutable std::vector<int> pairs_;     // vertex pairs (i, j): j's triangles are i's candidates
  mutable std::vector<double> reach_;  // per vertex: delta + (longest edge of its triangles)/sqrt(3)
  mutable std::vector<double> face_longest2_;  // per face: its longest edge, squared
  mutable std::vector<std::vector<Record>> records_;
  // add_gradient of a large system: one gradient per slab of chunks of records (zero between
  // calls).
  static constexpr int kScatterSlabs = 4;
  mutable std::vector<double> slab_gradients_;
  mutable std::vector<char> slab_touched_;  // per slab, per block of kChunkVertices vertices: written
};

inline Eigen::Vector3d closest_triangle_weights(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double s = va + vb + vc;
  if (!(s > 0)) return {1, 0, 0};  // degenerate (zero area) and not caught above
  const double v = vb / s, w = vc / s;
  return {1 - v - w, v, w};
}

}  // namespace cmp::shell
