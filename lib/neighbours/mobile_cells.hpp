#pragma once
// A linked-cell grid for Monte Carlo: particles move one at a time, so each cell keeps its
// members' coordinates contiguous (structure of arrays, padded to a multiple of 4 with far-away
// sentinels) and a move relocates one particle in O(1). The energy loops over a cell then run
// branch-free over plain arrays, which the compiler vectorises.
// The grid is a non-periodic cube holding all points (e.g. the bounding cube of a sphere).
#include "mesh/tri_mesh.hpp"
#include <vector>

namespace cmp::neighbours {

class MobileCells {
 public:
  static constexpr double kFarAway = 1e100;  // coordinate of empty slots: never within cutoff
  static constexpr int kLanes = 4;           // slots per cell are a multiple of this

  // Cube [lower, lower + length]^3 cut into cells of side >= cutoff. Points outside are
  // clamped into the boundary cells (correct, only slower).
  MobileCells(const Eigen::Vector3d& lower, double length, double cutoff);

  // Places every point of X (#N by 3); replaces any previous content.
  void assign(const mesh::VertexMatrix& X);
  // Moves particle i to p, relocating it when it changes cell.
  void move(int i, const Eigen::Vector3d& p);

  int cell_of(const Eigen::Vector3d& p) const;
  int cells_per_axis() const { return n_; }
  // Calls f(cell) for the up to 27 cells around `cell` that exist.
  template <class Fn>
  void for_each_stencil_cell(int cell, Fn&& f) const {
    const int cx = cell % n_, cy = (cell / n_) % n_, cz = cell / (n_ * n_);
    for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, n_ - 1); ++z)
      for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, n_ - 1); ++y)
        for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, n_ - 1); ++x) f(x + n_ * (y + n_ * z));
  }

  // Members of a cell: slots [cell * capacity, cell * capacity + padded_count(cell)).
  int count(int cell) const { return counts_[cell]; }
  int padded_count(int cell) const { return (counts_[cell] + kLanes - 1) / kLanes * kLanes; }
  int capacity() const { return capacity_; }
  const double* xs() const { return x_.data(); }
  const double* ys() const { return y_.data(); }
  const double* zs() const { return z_.data(); }
  int cell_of_particle(int i) const { return cell_[i]; }
  int slot_of_particle(int i) const { return slot_[i]; }  // absolute slot index

  // Temporarily hides particle i from the energy loops (its slot reads as far away), so a
  // particle's energy can be summed over its own cell without a self-test; restore() undoes.
  void hide(int i) { x_[slot_[i]] = kFarAway; }
  void restore(int i, double x) { x_[slot_[i]] = x; }

 private:
  void grow(int min_capacity);
  void append(int i, int cell, const Eigen::Vector3d& p);
  void remove(int i);

  Eigen::Vector3d lower_;
  double cell_size_;
  int n_ = 1, capacity_ = kLanes * 4;
  std::vector<int> counts_;
  std::vector<double> x_, y_, z_;  // ncells * capacity
  std::vector<int> ids_;           // particle id in each slot, -1 when empty
  std::vector<int> cell_, slot_;   // per particle
};

}  // namespace cmp::neighbours
