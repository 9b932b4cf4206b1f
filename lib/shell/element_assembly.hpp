#pragma once
// Gradient assembly of a mesh energy term (triangles, hinges, edges) on all threads, with the
// same bits on 1 thread or many: no two threads ever add into the same double, and every sum
// has one fixed order.
//
// Two passes over fixed chunks, in one parallel region per call:
//   1. element pass: a kernel writes each element's force on each of its `arity` corners into
//      that corner's slot (3 doubles) of a force buffer laid out vertex by vertex: vertex v's
//      slots are consecutive, its incident elements in element order (then corner order);
//   2. gather pass: each vertex adds up its consecutive slots, in that order, and adds the
//      sum into g.
// A mesh of separate pieces numbered one after another (a packing of shells) is cut into
// blocks of whole pieces, each running both passes in turn (its slots still in cache) and the
// blocks on all threads; the sums are the same.
// The kernel's stores are scattered and the gather's loads stream; the other way round (slots
// in element order, gathered through an index) the loads wait on memory: a third of a force
// evaluation of 50 shells of 2562 vertices. The sums and their order are the same either way.
// Chunks are handed out dynamically, so a thread slowed by another process gives its share
// away. Small meshes run both passes on the calling thread with no OpenMP construct at all
// (a fork/join would cost more than the work); the bits are the same either way. Energies
// are summed per fixed chunk and the chunk sums added in chunk order.
//
// The buffers are mutable state of a const object: one object must not assemble from two
// threads at once (each shell system owns its terms).
#include "core/fixed_chunks.hpp"

#include <omp.h>

#include <vector>

namespace cmp::shell {

// Where a kernel stores the force on corner k of element e: the 3 doubles at at(k, e).
struct CornerForces {
  static constexpr int kMaxArity = 4;
  double* buffer;
  const int* slot[kMaxArity];  // slot[k][e]: the slot of corner k of element e
  double* at(int k, long e) const { return buffer + 3L * slot[k][e]; }
};

class ElementAssembly {
 public:
  ElementAssembly() = default;
  // corners: `arity` vertex indices per element, element after element (all in [0, vertex_count)).
  // Throws std::invalid_argument for an index outside the mesh, an arity above
  // CornerForces::kMaxArity, or a buffer of 2^31 doubles or more.
  ElementAssembly(const std::vector<int>& corners, int arity, long vertex_count);

  long element_count() const { return elements_; }
  // Corner k (0 .. arity-1) of every element: element_count() indices.
  const int* corner(int k) const { return corners_.data() + k * elements_; }
  // Where a kernel stores dE/dx on the corners of the elements.
  CornerForces corner_forces() const;

  // kernel(begin, end) fills the corner forces of elements [begin, end); then every
  // vertex's sum is added into g (3 #V doubles).
  template <class Kernel>
  void assemble(Kernel&& kernel, double* g) const {
    if (blocks_.size() > 2) {
      // Separate pieces (the shells of a packing): each block's slots are written and summed
      // while they are still in cache; blocks run on all threads.
      const int nb = static_cast<int>(blocks_.size()) - 1;
      const auto block = [&](int b) {
        kernel(blocks_[b].element, blocks_[b + 1].element);
        gather(blocks_[b].vertex, blocks_[b + 1].vertex, g);
      };
      if (!parallel()) {
        for (int b = 0; b < nb; ++b) block(b);
      } else {
#pragma omp parallel for schedule(dynamic, 1)
        for (int b = 0; b < nb; ++b) block(b);
      }
      return;
    }
    const int ec = element_chunks_, vc = vertex_chunks_;
    const auto elements = [&](int c) { kernel(chunk_begin(elements_, ec, c), chunk_begin(elements_, ec, c + 1)); };
    const auto vertices = [&](int c) { gather(chunk_begin(vertices_, vc, c), chunk_begin(vertices_, vc, c + 1), g); };
    if (!parallel()) {
      for (int c = 0; c < ec; ++c) elements(c);
      for (int c = 0; c < vc; ++c) vertices(c);
      return;
    }
#pragma omp parallel
    {
#pragma omp for schedule(dynamic, 1)
      for (int c = 0; c < ec; ++c) elements(c);
#pragma omp for schedule(dynamic, 1)
      for (int c = 0; c < vc; ++c) vertices(c);
    }
  }

  // The sum over the elements of partial(begin, end) (the sum over a range), chunk by chunk.
  template <class Partial>
  double sum(Partial&& partial) const {
    const int ec = element_chunks_;
    double* sums = chunk_sums_.data();
    const auto chunk = [&](int c) { sums[c] = partial(chunk_begin(elements_, ec, c), chunk_begin(elements_, ec, c + 1)); };
    if (!parallel()) {
      for (int c = 0; c < ec; ++c) chunk(c);
    } else {
#pragma omp parallel for schedule(dynamic, 1)
      for (int c = 0; c < ec; ++c) chunk(c);
    }
    double total = 0;
    for (int c = 0; c < ec; ++c) total += sums[c];
    return total;
  }

  // Elements per chunk.
  static constexpr long kChunkElements = 512;
  // Elements per block at least, where the mesh falls into pieces (the last block may be smaller).
  static constexpr long kBlockElements = 4096;
  // The element count from which the passes run on all threads (default 65536). Measured on
  // 2 cores (bench_shell terms LEVEL): a parallel region costs ~20 us with the toolkit's
  // sleeping wait, and the gather reads element slots the other core wrote, so one shell of
  // 10242 vertices (20480 triangles, 30720 hinges) computed its forces 1.2 times slower on two
  // threads than on one, while 40962 vertices (the size of 16 shells of 2562) ran 1.5 times
  // faster. The setter is for tests (same bits on any thread count at small sizes) and
  // benchmarks; it is not thread-safe against running assemblies.
  static long parallel_elements();
  static void set_parallel_elements(long count);
  // Whether a pass over this many elements runs on all threads (the rule above, and never
  // inside another parallel region).
  static bool runs_parallel(long elements) {
    return elements >= parallel_elements() && omp_get_max_threads() > 1 && !omp_in_parallel();
  }

 private:
  bool parallel() const { return runs_parallel(elements_); }
  // Adds the sums of vertices [begin, end) into g.
  void gather(long begin, long end, double* g) const;

  // Blocks of the mesh that share no vertex: elements [element, next's element) touch only
  // vertices [vertex, next's vertex) and no other element touches those (both in order), ending
  // with {element_count(), vertex_count}; a single block when the mesh does not fall apart.
  struct Block {
    long element, vertex;
  };
  std::vector<Block> blocks_;
  long elements_ = 0, vertices_ = 0;
  int arity_ = 1, element_chunks_ = 1, vertex_chunks_ = 1;
  std::vector<int> corners_;        // arity columns of element_count() indices
  std::vector<int> first_;  // vertex v's slots are first_[v] .. first_[v + 1]
  std::vector<int> slot_;   // the slot of corner k of element e at k element_count() + e
  mutable std::vector<double> buffer_, chunk_sums_;
};

// Tiles for vector lanes: a force pass copies the corner positions of up to kTile elements into
// unit-stride rows (row 3k + r: component r of corner k), computes on the rows in a loop the
// compiler vectorises (the same operations in every lane, so the same bits as one lane), and
// copies the result rows back into the corner-force buffers.
constexpr int kTile = 64;

// P[(3k + r) kTile + l] = x[3 corner_k[t0 + l] + r] for the m elements from t0.
template <int Arity>
inline void load_tile(const double* x, const int* const* corners, long t0, int m, double* P) {
  for (int k = 0; k < Arity; ++k)
    for (int l = 0; l < m; ++l)
      for (int r = 0; r < 3; ++r) P[(3 * k + r) * kTile + l] = x[3 * corners[k][t0 + l] + r];
}

// F.at(k, t0 + l)[r] = O[(3k + r) kTile + l] for the m elements from t0.
template <int Arity>
inline void store_tile(const double* O, const CornerForces& F, long t0, int m) {
  for (int k = 0; k < Arity; ++k)
    for (int l = 0; l < m; ++l) {
      double* f = F.at(k, t0 + l);
      for (int r = 0; r < 3; ++r) f[r] = O[(3 * k + r) * kTile + l];
    }
}

}  // namespace cmp::shell
