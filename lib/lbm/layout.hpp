#pragma once
// Where a population and a link live in memory (internal to lib/lbm): blocks of kBatch
// nodes, each block holding its 19 populations direction by direction (an array of
// structures of arrays): population (q, n) at 19*kBatch*(n / kBatch) + kBatch*q + n % kBatch,
// link (q, n), q = 1..18, at 18*kBatch*(n / kBatch) + kBatch*(q - 1) + n % kBatch. A sweep
// over consecutive nodes then reads one stream of populations and one of links instead of
// 19 + 18 separate streams (which defeated the hardware prefetchers and the TLB).
#include "lbm/d3q19.hpp"

#include <cstddef>
#include <cstdint>

namespace cmp::lbm {

inline constexpr int kBatch = 8;

constexpr std::size_t pop_slot(int q, long n) {
  return static_cast<std::size_t>(kQ * kBatch * (n / kBatch) + kBatch * q + n % kBatch);
}

constexpr std::size_t link_index(int q, long n) {
  return static_cast<std::size_t>((kQ - 1) * kBatch * (n / kBatch) + kBatch * (q - 1) + n % kBatch);
}

// The node of population slot s.
constexpr long slot_node(std::size_t s) {
  const long block = static_cast<long>(s / (kQ * kBatch));
  return block * kBatch + static_cast<long>(s % kBatch);
}

}  // namespace cmp::lbm
