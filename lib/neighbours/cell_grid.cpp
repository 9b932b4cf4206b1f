#include "neighbours/cell_grid.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <string>

namespace cmp::neighbours {

namespace {
const char* const kAxis[3] = {"x", "y", "z"};

// A relative margin on the cell width: with cells at least cutoff (1 + kMargin) wide, the
// round-off in computing a point's cell (~1e-16 of its coordinate) cannot put two points
// closer than the cutoff two cells apart.
constexpr double kMargin = 1e-10;

void check_box(const Box& box, double cutoff) {
  if (!(cutoff > 0) || !std::isfinite(cutoff))
    throw UsageError("cell grid: the cutoff must be positive and finite, got " + std::to_string(cutoff));
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(box.lower[a]) || !std::isfinite(box.lengths[a]) || box.lengths[a] < 0)
      throw UsageError(std::string("cell grid: the box along ") + kAxis[a] + " must be finite with a length >= 0");
    if (box.periodic[a] && !(cutoff <= box.lengths[a] / 2))
      throw UsageError(std::string("cell grid: the cutoff ") + std::to_string(cutoff) + " exceeds half the periodic length " +
                       std::to_string(box.lengths[a]) + " along " + kAxis[a] +
                       "; a pair could then be within the cutoff through two images");
  }
}

Eigen::Vector3i automatic_cells(const Box& box, double cutoff) {
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) {
    const double fit = std::floor(box.lengths[a] / (cutoff * (1 + kMargin)));
    n[a] = static_cast<int>(std::clamp(fit, 1.0, static_cast<double>(CellGrid::kMaxCells)));
  }
  // Coarsen the finest axis until the total fits: wider cells stay correct.
  while (static_cast<long>(n[0]) * n[1] * n[2] > CellGrid::kMaxCells) {
    int a = 0;
    for (int b = 1; b < 3; ++b)
      if (n[b] > n[a]) a = b;
    n[a] = std::max(1, n[a] * 3 / 4);
  }
  return n;
}
}  // namespace

CellGrid::CellGrid(const Box& box, double cutoff) : CellGrid(box, cutoff, Eigen::Vector3i::Zero()) {}

CellGrid::CellGrid(const Box& box, double cutoff, const Eigen::Vector3i& cells_per_axis)
    : box_(box), cutoff_(cutoff), cutoff2_(cutoff * cutoff) {
  check_box(box, cutoff);
  const Eigen::Vector3i most = automatic_cells(box, cutoff);
  if (cells_per_axis.isZero()) {
    cells_ = most;
  } else {
    for (int a = 0; a < 3; ++a)
      if (cells_per_axis[a] < 1 || cells_per_axis[a] > most[a])
        throw UsageError(std::string("cell grid: ") + std::to_string(cells_per_axis[a]) + " cells along " + kAxis[a] +
                         ": must be between 1 and " + std::to_string(most[a]) + " (cells at least a cutoff wide)");
    cells_ = cells_per_axis;
  }
  for (int a = 0; a < 3; ++a) {
    const double L = box.lengths[a];
    periods_[a] = box.periodic[a] ? L : 0;
    inverse_periods_[a] = box.periodic[a] ? 1 / L : 0;
    inverse_lengths_[a] = L > 0 ? 1 / L : 0;
  }
  cell_start_.assign(static_cast<std::size_t>(cell_count()) + 1, 0);
}

int CellGrid::cell_of(const Eigen::Vector3d& p) const {
  int c[3];
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(p[a])) throw ComputationError("cell grid: a point has a non-finite coordinate");
    double s = (p[a] - box_.lower[a]) * inverse_lengths_[a];  // in [0, 1) inside the box
    s = box_.periodic[a] ? s - std::floor(s) : std::clamp(s, 0.0, 1.0);
    c[a] = std::min(static_cast<int>(s * cells_[a]), cells_[a] - 1);
  }
  return c[0] + cells_[0] * (c[1] + cells_[1] * c[2]);
}

void CellGrid::build(const mesh::VertexMatrix& X) {
  const int n = static_cast<int>(X.rows());
  const int cells = cell_count();
  particle_cell_.resize(static_cast<std::size_t>(n));
  std::fill(cell_start_.begin(), cell_start_.end(), 0);
  for (int i = 0; i < n; ++i) {
    const int c = cell_of(X.row(i).transpose());
    particle_cell_[static_cast<std::size_t>(i)] = c;
    ++cell_start_[static_cast<std::size_t>(c) + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  // Scatter with cell_start_[c] as the cursor of cell c; afterwards it points at the end of c,
  // i.e. the start of c + 1, so one shift restores the starts. Stable: ascending in a cell.
  sorted_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) sorted_[static_cast<std::size_t>(cell_start_[particle_cell_[i]]++)] = i;
  for (int c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

void CellGrid::check_rows(const mesh::VertexMatrix& X) const {
  if (X.rows() != static_cast<Eigen::Index>(sorted_.size()))
    throw UsageError("cell grid: built for " + std::to_string(sorted_.size()) + " points, asked about " +
                     std::to_string(X.rows()));
}

}  // namespace cmp::neighbours
