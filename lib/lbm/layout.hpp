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
#include <type_traits>

namespace cmp::lbm {

inline constexpr int kBatch = 8;

// The order of the fluid nodes (lbm/link_table.cpp): bricks of kBrickPlanes planes along the
// flow axis and brick_rows() rows of the slower cross axis; brick after brick along the cross
// axis, then along the flow axis; inside a brick plane by plane, row by row, along the fastest
// axis. A node's neighbours in the next plane are then brick_rows() rows ahead in memory, not
// a whole plane, so the lines an odd step gathers for one block are still in the core's L2
// cache when the block on the other side writes back to them (two whole planes, 5 MB on a dense
// 128^2 box, were not): bricks took bench_lbm's odd steps on two threads from 79 to 92 MLUPS
// on the dense box and from 59.5 to 61.7 on the porous one (one thread: no change; both
// layouts stepped in turn in one process). kBrickPlanes planes are still one
// contiguous node range, so the MPI split along the axis (slab_decomposition.hpp) gives each rank whole bricks.
inline constexpr int kBrickPlanes = 16;
inline constexpr int kBrickSites = 2048;  // lattice sites of one brick plane (~300 kB dense)
constexpr int brick_rows(int row_length) { return row_length >= kBrickSites ? 1 : kBrickSites / row_length; }

constexpr std::size_t pop_slot(int q, long n) {
  return static_cast<std::size_t>(kQ * kBatch * (n / kBatch) + kBatch * q + n % kBatch);
}

constexpr std::size_t link_index(int q, long n) {
  return static_cast<std::size_t>((kQ - 1) * kBatch * (n / kBatch) + kBatch * (q - 1) + n % kBatch);
}

// Bit q (q = 1..18) set when link line q of the block starting at node `base` holds kBatch
// consecutive slots (the neighbours along c_q are a run of nodes that fills one block line, as
// inside long fluid runs when the shift lines up with the blocks: on a dense box the 8 directions
// across the lane axis); the odd sweep moves such a line with one vector load and one store.
inline std::uint32_t consecutive_lines(const std::uint32_t* links, long base) {
  std::uint32_t bits = 0;
  for (int q = 1; q < kQ; ++q) {
    const std::uint32_t* line = links + link_index(q, base);
    bool consecutive = true;
    for (int k = 1; k < kBatch; ++k) consecutive = consecutive && line[k] == line[0] + static_cast<std::uint32_t>(k);
    if (consecutive) bits |= std::uint32_t{1} << q;
  }
  return bits;
}

// The node of population slot s.
constexpr long slot_node(std::size_t s) {
  const long block = static_cast<long>(s / (kQ * kBatch));
  return block * kBatch + static_cast<long>(s % kBatch);
}

// The direction index of population slot s (opposite directions share a weight, so the AA
// pattern's swapped slots do not matter to stored_offset()).
constexpr int slot_direction(std::size_t s) { return static_cast<int>(s % (kQ * kBatch) / kBatch); }

// What a slot stores is f_q - stored_offset<Real>(q): float storage keeps the deviation from
// the rest weights w_q (f_q is w_q + O(drop, u), so float's 24 bits go to the part that moves;
// f_q itself in float loses the small non-equilibrium part to cancellation, 2 % of kappa on a
// small image); double keeps f_q as it is.
template <class Real>
constexpr double stored_offset(int q) {
  if constexpr (std::is_same_v<Real, float>) return weight(q);
  else return 0.0;
}

// f_q from slot s and back (the boundary passes; the sweep kernel does the same inline).
template <class Real>
inline double load_population(const Real* F, std::size_t s) {
  if constexpr (std::is_same_v<Real, float>) return static_cast<double>(F[s]) + weight(slot_direction(s));
  else return F[s];
}
template <class Real>
inline void store_population(Real* F, std::size_t s, double f) {
  if constexpr (std::is_same_v<Real, float>) F[s] = static_cast<float>(f - weight(slot_direction(s)));
  else F[s] = f;
}

}  // namespace cmp::lbm
