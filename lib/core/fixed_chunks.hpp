#pragma once
// Work cut into a fixed number of chunks, whatever the thread count: per-chunk sums added in
// chunk order give the same bits on 1 thread or 64, so "same seed, same result" holds for
// parallel reductions too (FIRE's vector passes, Hertz forces of large systems).
#include <cstddef>

namespace cmp {

// Start of chunk c (0 .. chunks) of [0, total), on multiples of `granularity` (total must be
// one); chunk c is [chunk_begin(c), chunk_begin(c + 1)).
inline std::ptrdiff_t chunk_begin(std::ptrdiff_t total, int chunks, int c, std::ptrdiff_t granularity = 1) {
  return total / granularity * c / chunks * granularity;
}

// body(c) for c = 0 .. chunks-1: one chunk runs directly, with no OpenMP construct at all
// (even an if(false) parallel region costs about a microsecond, as long as a whole FIRE
// iteration of 50 spheres); several run on all threads.
template <class Body>
void for_each_chunk(int chunks, Body&& body) {
  if (chunks == 1) {
    body(0);
    return;
  }
  // Dynamic: when another process slows one thread down, the others take its chunks.
#pragma omp parallel for schedule(dynamic, 1)
  for (int c = 0; c < chunks; ++c) body(c);
}

// The same chunks, on all threads only when `parallel` (a pass too short to pay for a
// fork/join runs them in order on this one; the bits are the same either way).
template <class Body>
void for_each_chunk(int chunks, bool parallel, Body&& body) {
  if (!parallel) {
    for (int c = 0; c < chunks; ++c) body(c);
    return;
  }
  for_each_chunk(chunks, body);
}

}  // namespace cmp
