#include "neighbours/mobile_cells.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::neighbours {

MobileCells::MobileCells(const Eigen::Vector3d& lower, double length, double cutoff)
    : lower_(lower) {
  if (!(length > 0) || !(cutoff > 0)) throw UsageError("cell grid: length and cutoff must be positive");
  // Cap the grid at 64^3 cells (~120 MB of slots): beyond that, memory for the mostly empty
  // interior of a sphere would dominate; coarser cells stay correct, only slower.
  n_ = std::clamp(static_cast<int>(std::floor(length / cutoff)), 1, 64);
  cell_size_ = length / n_;
  const std::size_t cells = static_cast<std::size_t>(n_) * n_ * n_;
  counts_.assign(cells, 0);
  x_.assign(cells * capacity_, kFarAway);
  y_.assign(cells * capacity_, kFarAway);
  z_.assign(cells * capacity_, kFarAway);
  ids_.assign(cells * capacity_, -1);
}

int MobileCells::cell_of(const Eigen::Vector3d& p) const {
  int c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = std::clamp(static_cast<int>(std::floor((p[k] - lower_[k]) / cell_size_)), 0, n_ - 1);
  return c[0] + n_ * (c[1] + n_ * c[2]);
}

void MobileCells::grow(int min_capacity) {
  int capacity = capacity_;
  while (capacity < min_capacity) capacity *= 2;
  if (capacity == capacity_) return;
  const std::size_t cells = counts_.size();
  std::vector<float> x(cells * capacity, kFarAway), y(x), z(x);
  std::vector<int> ids(cells * capacity, -1);
  for (std::size_t c = 0; c < cells; ++c)
    for (int k = 0; k < counts_[c]; ++k) {
      const std::size_t from = c * capacity_ + k, to = c * capacity + k;
      x[to] = x_[from], y[to] = y_[from], z[to] = z_[from], ids[to] = ids_[from];
      slot_[ids_[from]] = static_cast<int>(to);
    }
  x_.swap(x), y_.swap(y), z_.swap(z), ids_.swap(ids);
  capacity_ = capacity;
}

void MobileCells::append(int i, int cell, const Eigen::Vector3d& p) {
  if (counts_[cell] + 1 > capacity_) grow(counts_[cell] + kLanes);
  const std::size_t s = static_cast<std::size_t>(cell) * capacity_ + counts_[cell]++;
  x_[s] = static_cast<float>(p[0]), y_[s] = static_cast<float>(p[1]), z_[s] = static_cast<float>(p[2]);
  ids_[s] = i;
  cell_[i] = cell, slot_[i] = static_cast<int>(s);
}

void MobileCells::remove(int i) {
  // Fill i's slot with the cell's last member, then clear the last slot.
  const int cell = cell_[i];
  const std::size_t s = slot_[i], last = static_cast<std::size_t>(cell) * capacity_ + --counts_[cell];
  if (s != last) {
    x_[s] = x_[last], y_[s] = y_[last], z_[s] = z_[last], ids_[s] = ids_[last];
    slot_[ids_[s]] = static_cast<int>(s);
  }
  x_[last] = y_[last] = z_[last] = kFarAway;
  ids_[last] = -1;
}

void MobileCells::assign(const mesh::VertexMatrix& X) {
  std::fill(counts_.begin(), counts_.end(), 0);
  std::fill(x_.begin(), x_.end(), kFarAway);
  std::fill(y_.begin(), y_.end(), kFarAway);
  std::fill(z_.begin(), z_.end(), kFarAway);
  std::fill(ids_.begin(), ids_.end(), -1);
  cell_.assign(X.rows(), -1);
  slot_.assign(X.rows(), -1);
  for (Eigen::Index i = 0; i < X.rows(); ++i) {
    const Eigen::Vector3d p = X.row(i);
    append(static_cast<int>(i), cell_of(p), p);
  }
}

void MobileCells::move(int i, const Eigen::Vector3d& p) {
  const int cell = cell_of(p);
  if (cell == cell_[i]) {
    const std::size_t s = slot_[i];
    x_[s] = static_cast<float>(p[0]), y_[s] = static_cast<float>(p[1]), z_[s] = static_cast<float>(p[2]);
    return;
  }
  remove(i);
  append(i, cell, p);
}

}  // namespace cmp::neighbours
