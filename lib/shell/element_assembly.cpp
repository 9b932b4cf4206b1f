#include "shell/element_assembly.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

namespace cmp::shell {

namespace {
long parallel_element_threshold = 65536;
}  // namespace

long ElementAssembly::parallel_elements() { return parallel_element_threshold; }
void ElementAssembly::set_parallel_elements(long count) { parallel_element_threshold = count; }

ElementAssembly::ElementAssembly(const std::vector<int>& corners, int arity, long vertex_count)
    : elements_(static_cast<long>(corners.size()) / arity), vertices_(vertex_count), arity_(arity) {
  if (arity <= 0 || corners.size() % static_cast<std::size_t>(arity) != 0)
    throw std::invalid_argument("element assembly: corner list is not a whole number of elements");
  if (arity > CornerForces::kMaxArity) throw std::invalid_argument("element assembly: too many corners per element");
  if (3L * arity * elements_ >= INT_MAX) throw std::invalid_argument("element assembly: too many elements");
  element_chunks_ = static_cast<int>(std::max(1L, (elements_ + kChunkElements - 1) / kChunkElements));
  vertex_chunks_ = static_cast<int>(std::max(1L, (vertices_ + kChunkElements - 1) / kChunkElements));
  corners_.resize(corners.size());
  first_.assign(static_cast<std::size_t>(vertices_) + 1, 0);
  for (long e = 0; e < elements_; ++e)
    for (int k = 0; k < arity; ++k) {
      const int v = corners[static_cast<std::size_t>(arity * e + k)];
      if (v < 0 || v >= vertices_)
        throw std::invalid_argument("element assembly: element " + std::to_string(e) + " refers to vertex " +
                                    std::to_string(v) + " of a mesh of " + std::to_string(vertices_));
      corners_[static_cast<std::size_t>(k * elements_ + e)] = v;
      ++first_[v + 1];
    }
  for (long v = 0; v < vertices_; ++v) first_[v + 1] += first_[v];
  // Each vertex's slots in element order (then corner order): the order of its sum.
  slot_.resize(corners.size());
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (long e = 0; e < elements_; ++e)
    for (int k = 0; k < arity; ++k)
      slot_[static_cast<std::size_t>(k * elements_ + e)] = next[corners[static_cast<std::size_t>(arity * e + k)]]++;
  // Block boundaries: before element s where every earlier element's highest vertex lies below
  // every later element's lowest one.
  std::vector<int> later_lowest(static_cast<std::size_t>(elements_) + 1, static_cast<int>(vertices_));
  for (long e = elements_ - 1; e >= 0; --e) {
    int lowest = later_lowest[e + 1];
    for (int k = 0; k < arity; ++k) lowest = std::min(lowest, corners_[k * elements_ + e]);
    later_lowest[e] = lowest;
  }
  blocks_.push_back({0, 0});
  int highest = -1;
  for (long e = 0; e < elements_; ++e) {
    for (int k = 0; k < arity; ++k) highest = std::max(highest, corners_[k * elements_ + e]);
    const long s = e + 1;
    if (s < elements_ && s - blocks_.back().element >= kBlockElements && highest < later_lowest[s])
      blocks_.push_back({s, highest + 1});
  }
  blocks_.push_back({elements_, vertices_});
  buffer_.assign(static_cast<std::size_t>(3 * arity * elements_), 0.0);
  chunk_sums_.assign(static_cast<std::size_t>(element_chunks_), 0.0);
}

CornerForces ElementAssembly::corner_forces() const {
  CornerForces f{buffer_.data(), {}};
  for (int k = 0; k < arity_; ++k) f.slot[k] = slot_.data() + k * elements_;
  return f;
}

void ElementAssembly::gather(long begin, long end, double* g) const {
  const double* B = buffer_.data();
  for (long v = begin; v < end; ++v) {
    double sx = 0, sy = 0, sz = 0;
    for (long k = first_[v]; k < first_[v + 1]; ++k) {
      const double* b = B + 3 * k;
      sx += b[0], sy += b[1], sz += b[2];
    }
    g[3 * v] += sx, g[3 * v + 1] += sy, g[3 * v + 2] += sz;
  }
}

}  // namespace cmp::shell
