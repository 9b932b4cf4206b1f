#pragma once
// A Verlet list for single-particle Monte Carlo. Each particle i has a reference position
// r_i and lists every k with |r_i - r_k| < cutoff + skin (padded to a multiple of 8 with a
// far-away sentinel), next to single-precision copies of all current positions: an energy is
// then one branch-free pass over ~60 partners instead of a scan of 27 cells.
// Invariant: every particle is within skin/2 of its reference, so two unlisted particles are
// at least `cutoff` apart. A trial position within skin/2 of r_i therefore sees all its
// partners (covers()); a particle accepted beyond that is re-listed alone, around its new
// position (move()), without a global rebuild, which matters in hot, fluid states where
// particles keep wandering.
#include "mesh/tri_mesh.hpp"
#include "neighbours/mobile_cells.hpp"
#include <vector>

namespace cmp::neighbours {

class MonteCarloVerletList {
 public:
  static constexpr int kLanes = MobileCells::kLanes;

  // skin must not exceed cutoff / 1.5 (the cell stencil of a re-listing reaches 2 cells of
  // side >= cutoff); throws cmp::UsageError otherwise.
  MonteCarloVerletList(double cutoff, double skin);

  // Lists from scratch with references = X. `cells` holds X, with cells at least cutoff wide.
  void build(const mesh::VertexMatrix& X, const MobileCells& cells);

  // True when a trial position p of particle i is within skin/2 of i's reference.
  bool covers(int i, const double* p) const {
    const double dx = p[0] - reference_(i, 0), dy = p[1] - reference_(i, 1), dz = p[2] - reference_(i, 2);
    return dx * dx + dy * dy + dz * dz <= half_skin2_;
  }

  // Particle i was moved to X.row(i) (already in `cells`); if it left its skin it is
  // re-listed around its new position.
  void move(int i, const mesh::VertexMatrix& X, const MobileCells& cells);

  // Partners of i: ids [begin(i), begin(i) + padded_count(i)) of partner_ids(), padding
  // slots hold the sentinel id N whose position is far away.
  std::size_t begin(int i) const { return offsets_[i]; }
  int padded_count(int i) const { return (counts_[i] + kLanes - 1) / kLanes * kLanes; }
  int count(int i) const { return counts_[i]; }
  const int* partner_ids() const { return partner_.data(); }
  // Current positions (single precision), N + 1 entries with the sentinel last.
  const float* xs() const { return x_.data(); }
  const float* ys() const { return y_.data(); }
  const float* zs() const { return z_.data(); }
  long builds() const { return builds_; }
  long relists() const { return relists_; }

 private:
  // Everything within the list radius of point p by reference position (excluding i), sorted.
  void gather(int i, const Eigen::Vector3d& p, const MobileCells& cells, std::vector<int>& out) const;
  void erase_partner(int owner, int partner);
  bool append_partner(int owner, int partner);

  double cutoff_, skin_, radius2_, half_skin2_;
  int n_ = 0;
  long builds_ = 0, relists_ = 0;
  mesh::VertexMatrix reference_;
  std::vector<std::size_t> offsets_;  // N + 1; capacity of list i = offsets_[i+1] - offsets_[i]
  std::vector<int> counts_;           // N
  std::vector<int> partner_;          // partner ids, sentinel N in unused slots
  std::vector<float> x_, y_, z_;      // current positions, N + 1
  std::vector<int> scratch_old_, scratch_new_;
};

}  // namespace cmp::neighbours
