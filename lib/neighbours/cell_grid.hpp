#pragma once
// Linked cells: the O(N) path to every pair of points closer than a cutoff. The box is cut
// into cells at least `cutoff` wide, points are counting-sorted by cell (cell_start and
// sorted_indices, as in a compressed-row matrix, so a cell's members are contiguous), and a
// pair within the cutoff always lies in the same or in adjacent cells.
//
//   CellGrid grid(box, cutoff);
//   grid.build(X);                                        // O(N + cells)
//   grid.for_each_pair(X, [&](int i, int j, const Eigen::Vector3d& d, double r2) { ... });
//
// The loops are templates: the callback is inlined, nothing is allocated per pair.
#include "mesh/tri_mesh.hpp"
#include "neighbours/box.hpp"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace cmp::neighbours {

class CellGrid {
 public:
  // Cells per axis: floor(L / cutoff), at least 1 (a hair fewer when L is an exact multiple
  // of the cutoff, so that round-off in placing a point can never hide a pair). A zero length
  // (2D) gives one cell. The total is capped at kMaxCells by coarsening (still correct).
  // Throws cmp::UsageError unless cutoff > 0, every length >= 0 and finite, and
  // cutoff <= L/2 along every periodic axis (so that the minimum image is the only image
  // within the cutoff).
  CellGrid(const Box& box, double cutoff);
  // The same with chosen cells per axis, each in [1, the automatic count]: fewer, wider cells
  // (e.g. 1 or 2 along a periodic axis) are still correct. Throws cmp::UsageError otherwise.
  CellGrid(const Box& box, double cutoff, const Eigen::Vector3i& cells_per_axis);

  static constexpr long kMaxCells = 1L << 24;

  // Sorts the points X (#N by 3) into cells in O(N + cells), by counting sort. Points outside
  // a periodic box are wrapped into it; points outside a non-periodic box are placed in the
  // boundary cells (correct, only slower if many). X itself is not changed. Throws
  // cmp::ComputationError on a non-finite coordinate.
  void build(const mesh::VertexMatrix& X);

  // Calls f(i, j, d, r2) once per unordered pair i != j with r2 = |d|^2 < cutoff^2, where
  // d = x_i - x_j is the minimum image. X must be the points given to build() (same rows;
  // points moved since may be missed). Pairs come cell by cell: deterministic, but in no
  // particular order of i and j. Throws cmp::UsageError if X has a different number of rows.
  template <class Fn>
  void for_each_pair(const mesh::VertexMatrix& X, Fn&& f) const;
  // The pairs for_each_pair finds from the cells [cell_begin, cell_end) (each pair of points
  // comes from one cell only): consecutive ranges cover for_each_pair's calls in its order, so
  // ranges on several threads, joined in order, give the same pairs.
  template <class Fn>
  void for_each_pair_in_cells(const mesh::VertexMatrix& X, int cell_begin, int cell_end, Fn&& f) const;

  // Calls f(j, d, r2) for every point j of X with r2 = |d|^2 < cutoff^2, d = p - x_j (minimum
  // image). p need not be a point of X; if it is, that point comes too, with r2 = 0.
  template <class Fn>
  void for_each_neighbour(const mesh::VertexMatrix& X, const Eigen::Vector3d& p, Fn&& f) const;

  // Calls f(c) once for every distinct cell within one step of `cell` (itself included): up to
  // 27, fewer at non-periodic faces and when an axis has 1 or 2 cells.
  template <class Fn>
  void for_each_stencil_cell(int cell, Fn&& f) const;

  // d reduced to the minimum image (multiplies by precomputed 1/L: no division).
  Eigen::Vector3d minimum_image(const Eigen::Vector3d& d) const {
    Eigen::Vector3d r;
    for (int a = 0; a < 3; ++a) r[a] = cmp::minimum_image(d[a], periods_[a], inverse_periods_[a]);
    return r;
  }

  // Cell of a point: wrapped along periodic axes, clamped along the others.
  int cell_of(const Eigen::Vector3d& p) const;

  const Box& box() const { return box_; }
  double cutoff() const { return cutoff_; }
  const Eigen::Vector3i& cells_per_axis() const { return cells_; }
  int cell_count() const { return cells_[0] * cells_[1] * cells_[2]; }
  int particle_count() const { return static_cast<int>(sorted_.size()); }
  // Members of cell c: sorted_indices()[cell_start()[c] .. cell_start()[c + 1]), ascending.
  // sorted_indices() is also a cache-friendly order of the points (cell by cell).
  const std::vector<int>& cell_start() const { return cell_start_; }
  const std::vector<int>& sorted_indices() const { return sorted_; }
  int cell_of_particle(int i) const { return particle_cell_[static_cast<std::size_t>(i)]; }

 private:
  void check_rows(const mesh::VertexMatrix& X) const;
  // Distinct cell coordinates within one step of c along axis a: 1 to 3 of them.
  int axis_stencil(int a, int c, int out[3]) const;
  // x_i - x_j (minimum image) into d, returns |d|^2.
  double separation(const double* xi, const double* xj, double d[3]) const {
    double r2 = 0;
    for (int a = 0; a < 3; ++a) {
      d[a] = xi[a] - xj[a];
      d[a] = cmp::minimum_image(d[a], periods_[a], inverse_periods_[a]);
      r2 += d[a] * d[a];
    }
    return r2;
  }

  Box box_;
  double cutoff_, cutoff2_;
  Eigen::Vector3i cells_;
  double periods_[3], inverse_periods_[3];  // L and 1/L along periodic axes, 0 along the others
  double inverse_lengths_[3];               // 1/L, 0 for a zero length
  std::vector<int> cell_start_;             // cell_count() + 1
  std::vector<int> sorted_;                 // point indices, cell by cell
  std::vector<int> particle_cell_;          // cell of each point
};

// ---- templates ----

inline int CellGrid::axis_stencil(int a, int c, int out[3]) const {
  const int n = cells_[a];
  if (n == 1) {
    out[0] = 0;
    return 1;
  }
  if (box_.periodic[a]) {
    if (n == 2) {
      out[0] = c, out[1] = 1 - c;
      return 2;
    }
    out[0] = c == 0 ? n - 1 : c - 1, out[1] = c, out[2] = c == n - 1 ? 0 : c + 1;
    return 3;
  }
  int k = 0;
  if (c > 0) out[k++] = c - 1;
  out[k++] = c;
  if (c < n - 1) out[k++] = c + 1;
  return k;
}

template <class Fn>
void CellGrid::for_each_stencil_cell(int cell, Fn&& f) const {
  const int nx = cells_[0], ny = cells_[1];
  const int c[3] = {cell % nx, (cell / nx) % ny, cell / (nx * ny)};
  int s[3][3], k[3];
  for (int a = 0; a < 3; ++a) k[a] = axis_stencil(a, c[a], s[a]);
  for (int z = 0; z < k[2]; ++z)
    for (int y = 0; y < k[1]; ++y)
      for (int x = 0; x < k[0]; ++x) f(s[0][x] + nx * (s[1][y] + ny * s[2][z]));
}

template <class Fn>
void CellGrid::for_each_pair(const mesh::VertexMatrix& X, Fn&& f) const {
  for_each_pair_in_cells(X, 0, cell_count(), f);
}

template <class Fn>
void CellGrid::for_each_pair_in_cells(const mesh::VertexMatrix& X, int cell_begin, int cell_end, Fn&& f) const {
  check_rows(X);
  const double* x = X.data();
  const int* sorted = sorted_.data();
  for (int c = cell_begin; c < cell_end; ++c) {
    const int begin = cell_start_[c], end = cell_start_[c + 1];
    if (begin == end) continue;
    double d[3];
    for (int a = begin; a < end; ++a) {  // pairs inside the cell
      const int i = sorted[a];
      for (int b = a + 1; b < end; ++b) {
        const int j = sorted[b];
        const double r2 = separation(x + 3 * i, x + 3 * j, d);
        if (r2 < cutoff2_) f(i, j, Eigen::Vector3d(d[0], d[1], d[2]), r2);
      }
    }
    for_each_stencil_cell(c, [&](int other) {  // each pair of distinct cells once: other > c
      if (other <= c) return;
      const int other_begin = cell_start_[other], other_end = cell_start_[other + 1];
      for (int a = begin; a < end; ++a) {
        const int i = sorted[a];
        for (int b = other_begin; b < other_end; ++b) {
          const int j = sorted[b];
          const double r2 = separation(x + 3 * i, x + 3 * j, d);
          if (r2 < cutoff2_) f(i, j, Eigen::Vector3d(d[0], d[1], d[2]), r2);
        }
      }
    });
  }
}

template <class Fn>
void CellGrid::for_each_neighbour(const mesh::VertexMatrix& X, const Eigen::Vector3d& p, Fn&& f) const {
  check_rows(X);
  const double* x = X.data();
  const double q[3] = {p[0], p[1], p[2]};
  for_each_stencil_cell(cell_of(p), [&](int c) {
    double d[3];
    for (int b = cell_start_[c]; b < cell_start_[c + 1]; ++b) {
      const int j = sorted_[b];
      const double r2 = separation(q, x + 3 * j, d);
      if (r2 < cutoff2_) f(j, Eigen::Vector3d(d[0], d[1], d[2]), r2);
    }
  });
}

}  // namespace cmp::neighbours
