#include "neighbours/monte_carlo_verlet_list.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::neighbours {

namespace {
constexpr int kSpareSlots = 16;  // room per list for partners arriving between builds
}

MonteCarloVerletList::MonteCarloVerletList(double cutoff, double skin)
    : cutoff_(cutoff), skin_(skin), radius2_((cutoff + skin) * (cutoff + skin)), half_skin2_(0.25 * skin * skin) {
  if (!(cutoff > 0) || !(skin >= 0) || 1.5 * skin > cutoff)
    throw UsageError("Monte Carlo Verlet list: need cutoff > 0 and 0 <= skin <= cutoff / 1.5");
}

void MonteCarloVerletList::gather(int i, const Eigen::Vector3d& p, const MobileCells& cells,
                                  std::vector<int>& out) const {
  // Partners are sought by reference position, up to skin/2 away from their current one,
  // so the search reaches cutoff + 1.5 skin <= 2 cells.
  out.clear();
  const int* ids = cells.ids();
  cells.for_each_stencil_cell(
      cells.cell_of(p),
      [&](int c) {
        const std::size_t base = static_cast<std::size_t>(c) * cells.capacity();
        for (int k = 0; k < cells.count(c); ++k) {
          const int j = ids[base + k];
          const double dx = reference_(j, 0) - p[0], dy = reference_(j, 1) - p[1], dz = reference_(j, 2) - p[2];
          if (j != i && dx * dx + dy * dy + dz * dz < radius2_) out.push_back(j);
        }
      },
      2);
  std::sort(out.begin(), out.end());
}

void MonteCarloVerletList::build(const mesh::VertexMatrix& X, const MobileCells& cells) {
  ++builds_;
  n_ = static_cast<int>(X.rows());
  reference_ = X;
  x_.assign(n_ + 1, MobileCells::kFarAway);
  y_.assign(n_ + 1, MobileCells::kFarAway);
  z_.assign(n_ + 1, MobileCells::kFarAway);
  for (int i = 0; i < n_; ++i)
    x_[i] = static_cast<float>(X(i, 0)), y_[i] = static_cast<float>(X(i, 1)), z_[i] = static_cast<float>(X(i, 2));
  std::vector<std::vector<int>> lists(n_);
  for (int i = 0; i < n_; ++i) gather(i, X.row(i), cells, lists[i]);
  offsets_.assign(n_ + 1, 0);
  counts_.assign(n_, 0);
  for (int i = 0; i < n_; ++i)
    offsets_[i + 1] = offsets_[i] + (lists[i].size() + kSpareSlots + kLanes - 1) / kLanes * kLanes;
  partner_.assign(offsets_[n_], n_);
  for (int i = 0; i < n_; ++i) {
    counts_[i] = static_cast<int>(lists[i].size());
    std::copy(lists[i].begin(), lists[i].end(), partner_.begin() + offsets_[i]);
  }
}

void MonteCarloVerletList::erase_partner(int owner, int partner) {
  int* list = partner_.data() + offsets_[owner];
  int* last = list + --counts_[owner];
  *std::find(list, last + 1, partner) = *last;
  *last = n_;
}

bool MonteCarloVerletList::append_partner(int owner, int partner) {
  if (offsets_[owner] + counts_[owner] >= offsets_[owner + 1]) return false;
  partner_[offsets_[owner] + counts_[owner]++] = partner;
  return true;
}

void MonteCarloVerletList::move(int i, const mesh::VertexMatrix& X, const MobileCells& cells) {
  const double* p = X.row(i).data();
  x_[i] = static_cast<float>(p[0]), y_[i] = static_cast<float>(p[1]), z_[i] = static_cast<float>(p[2]);
  if (covers(i, p)) return;
  ++relists_;
  // Re-list i around its new position, its new reference, and mend its partners' lists.
  reference_.row(i) = X.row(i);
  gather(i, X.row(i), cells, scratch_new_);
  const std::size_t begin = offsets_[i];
  if (scratch_new_.size() > offsets_[i + 1] - begin) return build(X, cells);
  scratch_old_.assign(partner_.begin() + begin, partner_.begin() + begin + counts_[i]);
  std::sort(scratch_old_.begin(), scratch_old_.end());
  for (int k : scratch_old_)
    if (!std::binary_search(scratch_new_.begin(), scratch_new_.end(), k)) erase_partner(k, i);
  for (int k : scratch_new_)
    if (!std::binary_search(scratch_old_.begin(), scratch_old_.end(), k) && !append_partner(k, i))
      return build(X, cells);  // k's list is full: start afresh with room to spare
  std::fill(partner_.begin() + begin, partner_.begin() + offsets_[i + 1], n_);
  std::copy(scratch_new_.begin(), scratch_new_.end(), partner_.begin() + begin);
  counts_[i] = static_cast<int>(scratch_new_.size());
}

}  // namespace cmp::neighbours
