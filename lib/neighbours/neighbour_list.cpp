#include "neighbours/neighbour_list.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"

#include <omp.h>

#include <algorithm>
#include <string>

namespace cmp::neighbours {

namespace {
double checked_radius(double cutoff, double skin) {
  if (!(cutoff > 0) || !(skin >= 0) || !std::isfinite(cutoff + skin))
    throw UsageError("neighbour list: need cutoff > 0 and skin >= 0, got cutoff " + std::to_string(cutoff) + ", skin " +
                     std::to_string(skin));
  return cutoff + skin;
}

// Squared minimum-image distances from p to n candidates: a branch-free loop the compiler
// vectorises (roundpd for the images). period/inverse are 0 along non-periodic axes.
void squared_distances(const double p[3], const double* x, const double* y, const double* z, int n,
                       const double period[3], const double inverse[3], double* r2) {
  for (int m = 0; m < n; ++m) {
    double dx = p[0] - x[m], dy = p[1] - y[m], dz = p[2] - z[m];
    dx = cmp::minimum_image(dx, period[0], inverse[0]);
    dy = cmp::minimum_image(dy, period[1], inverse[1]);
    dz = cmp::minimum_image(dz, period[2], inverse[2]);
    r2[m] = dx * dx + dy * dy + dz * dz;
  }
}
}  // namespace

NeighbourList::NeighbourList(const Box& box, double cutoff, double skin)
    : cutoff_(cutoff), skin_(skin), grid_(box, checked_radius(cutoff, skin)) {}

void NeighbourList::build(const mesh::VertexMatrix& X) {
  grid_.build(X);
  const int n = static_cast<int>(X.rows());
  const int cells = grid_.cell_count();
  const double radius2 = radius() * radius();
  const std::vector<int>& start = grid_.cell_start();
  const std::vector<int>& sorted = grid_.sorted_indices();
  double period[3], inverse[3];
  for (int a = 0; a < 3; ++a) {
    period[a] = box().periodic[a] ? box().lengths[a] : 0;
    inverse[a] = box().periodic[a] ? 1 / box().lengths[a] : 0;
  }
  offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
  sorted_x_.resize(static_cast<std::size_t>(n)), sorted_y_.resize(static_cast<std::size_t>(n));
  sorted_z_.resize(static_cast<std::size_t>(n));
  scratch_.resize(static_cast<std::size_t>(std::max(omp_get_max_threads(), 1)));

#pragma omp parallel
  {
    // Positions in cell order: a cell's members, and neighbouring cells along x, are contiguous.
#pragma omp for schedule(static)
    for (int k = 0; k < n; ++k) {
      const int i = sorted[k];
      sorted_x_[k] = X(i, 0), sorted_y_[k] = X(i, 1), sorted_z_[k] = X(i, 2);
    }
    ThreadRows& mine = scratch_[static_cast<std::size_t>(omp_get_thread_num())];
    mine.neighbours.clear(), mine.particles.clear(), mine.starts.clear();
#pragma omp for schedule(dynamic, 64)
    for (int c = 0; c < cells; ++c) {
      if (start[c] == start[c + 1]) continue;
      // Gather the candidates of the whole stencil once, for all members of the cell.
      int stencil[27], stencil_size = 0, candidates = 0;
      grid_.for_each_stencil_cell(c, [&](int other) {
        stencil[stencil_size++] = other;
        candidates += start[other + 1] - start[other];
      });
      if (mine.ids.size() < static_cast<std::size_t>(candidates)) {
        for (auto* v : {&mine.x, &mine.y, &mine.z, &mine.r2}) v->resize(static_cast<std::size_t>(2 * candidates));
        mine.ids.resize(static_cast<std::size_t>(2 * candidates));
      }
      int m = 0;
      for (int s = 0; s < stencil_size; ++s)
        for (int k = start[stencil[s]]; k < start[stencil[s] + 1]; ++k, ++m) {
          mine.x[m] = sorted_x_[k], mine.y[m] = sorted_y_[k], mine.z[m] = sorted_z_[k];
          mine.ids[m] = sorted[k];
        }
      for (int a = start[c]; a < start[c + 1]; ++a) {
        const int i = sorted[a];
        const double p[3] = {sorted_x_[a], sorted_y_[a], sorted_z_[a]};
        squared_distances(p, mine.x.data(), mine.y.data(), mine.z.data(), candidates, period, inverse, mine.r2.data());
        // Branch-free selection: write every candidate, advance past the ones that qualify.
        const std::size_t row = mine.neighbours.size();
        mine.neighbours.resize(row + static_cast<std::size_t>(candidates));
        int* out = mine.neighbours.data() + row;
        int kept = 0;
        for (int k = 0; k < candidates; ++k) {
          out[kept] = mine.ids[k];
          kept += (mine.r2[k] < radius2) & (mine.ids[k] != i);
        }
        mine.neighbours.resize(row + static_cast<std::size_t>(kept));
        std::sort(mine.neighbours.begin() + static_cast<std::ptrdiff_t>(row), mine.neighbours.end());
        offsets_[static_cast<std::size_t>(i) + 1] = mine.neighbours.size() - row;
        mine.particles.push_back(i);
        mine.starts.push_back(row);
      }
    }
    // implicit barrier: every row length is known
#pragma omp single
    {
      for (int i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
      neighbours_.resize(offsets_[static_cast<std::size_t>(n)]);
    }
    // implicit barrier: offsets are final; each thread places its own rows
    for (std::size_t r = 0; r < mine.particles.size(); ++r) {
      const std::size_t i = static_cast<std::size_t>(mine.particles[r]);
      std::copy_n(mine.neighbours.begin() + static_cast<std::ptrdiff_t>(mine.starts[r]), offsets_[i + 1] - offsets_[i],
                  neighbours_.begin() + static_cast<std::ptrdiff_t>(offsets_[i]));
    }
  }
  reference_ = X;
  ++builds_;
}

bool NeighbourList::needs_rebuild(const mesh::VertexMatrix& X) const {
  if (X.rows() != reference_.rows() || builds_ == 0) return true;
  const double limit2 = skin_ * skin_ / 4;
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    if (grid_.minimum_image((X.row(i) - reference_.row(i)).transpose()).squaredNorm() > limit2) return true;
  return false;
}

bool NeighbourList::update(const mesh::VertexMatrix& X) {
  if (!needs_rebuild(X)) return false;
  build(X);
  return true;
}

}  // namespace cmp::neighbours
