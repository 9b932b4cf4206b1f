#pragma once
// A linked-cell grid for Monte Carlo: particles move one at a time, so each cell keeps its
// members' coordinates contiguous (structure of arrays, padded to a multiple of 8 with far-away
// sentinels) and a move relocates one particle in O(1). The energy loops over a cell then run
// branch-free over plain arrays, eight at a time. The copies are single precision: they serve
// screening and energy differences, while the caller keeps the double-precision positions.
// The grid is a non-periodic cube holding all points (e.g. the bounding cube of a sphere).
#include "mesh/tri_mesh.hpp"
#include <vector>

namespace cmp::neighbours {

class MobileCells {
 public:
  static constexpr float kFarAway = 1e30f;   // coordinate of empty slots: never within cutoff
  static constexpr int kLanes = 8;             // slots per cell are a multiple of this

  // Cube [lower, lower + length]^3 cut into cells of side >= cutoff. Points outside are
  // clamped into the boundary cells (correct, only slower).
  MobileCells(const Eigen::Vector3d& lower, double length, double cutoff);

  // Places every point of X (#N by 3); replaces any previous content.
  void assign(const mesh::VertexMatrix& X);
  // Moves particle i to p, relocating it when it changes cell.
  void move(int i, const Eigen::Vector3d& p);

  int cell_of(const Eigen::Vector3d& p) const;
  int cells_per_axis() const { return n_; }
  double cell_size() const { return cell_size_; }
  // Calls f(cell) for the cells within `reach` cells of `cell` along each axis that exist:
  // the 27 around it for reach 1 (everything within one cell side of any point in it).
  template <class Fn>
  void for_each_stencil_cell(int cell, Fn&& f, int reach = 1) const {
    const int cx = cell % n_, cy = (cell / n_) % n_, cz = cell / (n_ * n_);
    for (int z = std::max(cz - reach, 0); z <= std::min(cz + reach, n_ - 1); ++z)
      for (int y = std::max(cy - reach, 0); y <= std::min(cy + reach, n_ - 1); ++y)
        for (int x = std::max(cx - reach, 0); x <= std::min(cx + reach, n_ - 1); ++x) f(x + n_ * (y + n_ * z));
  }

  // Members of a cell: slots [cell * capacity, cell * capacity + padded_count(cell)).
  int count(int cell) const { return counts_[cell]; }
  int padded_count(int cell) const { return (counts_[cell] + kLanes - 1) / kLanes * kLanes; }
  int capacity() const { return capacity_; }
  const float* xs() const { return x_.data(); }
  const float* ys() const { return y_.data(); }
  const float* zs() const { return z_.data(); }
  const int* ids() const { return ids_.data(); }  // particle in each slot, -1 when empty
  int cell_of_particle(int i) const { return cell_[i]; }
  int slot_of_particle(int i) const { return slot_[i]; }  // absolute slot index

  // Temporarily hides particle i from the energy loops (its slot reads as far away), so a
  // particle's energy can be summed over its own cell without a self-test; restore() undoes.
  void hide(int i) { x_[slot_[i]] = kFarAway; }
  void restore(int i, double x) { x_[slot_[i]] = static_cast<float>(x); }

 private:
  void grow(int min_capacity);
  void append(int i, int cell, const Eigen::Vector3d& p);
  void remove(int i);

  Eigen::Vector3d lower_;
  double cell_size_;
  int n_ = 1, capacity_ = kLanes * 2;
  std::vector<int> counts_;
  std::vector<float> x_, y_, z_;   // ncells * capacity
  std::vector<int> ids_;           // particle id in each slot, -1 when empty
  std::vector<int> cell_, slot_;   // per particle
};

}  // namespace cmp::neighbours
