#include "voxel/label_components.hpp"

#include "core/errors.hpp"

#include <omp.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <bit>
#include <stdexcept>

namespace cmp::voxel {

Connectivity connectivity_from_name(const std::string& name) {
  if (name == "6") return Connectivity::Faces6;
  if (name == "18") return Connectivity::Edges18;
  if (name == "26") return Connectivity::Corners26;
  throw UsageError("--connectivity must be 6, 18 or 26, got '" + name + "'");
}

// How it works (profiled with perf on random images, where branches on voxel values are
// unpredictable and cost most of the time):
//  - every image row becomes a bit mask (64 voxels per word); runs of void voxels, and the
//    places where a run touches a run of an earlier neighbour row, are found with word
//    operations, so the branches are per union event, not per voxel;
//  - the label array is the union-find forest, whose nodes are the run starts (the other voxels
//    of a run find their start from the bits); a union links the larger root under the
//    smaller, so every root is the first voxel (in memory order) of its component, whatever
//    the order of the unions;
//  - z slabs are labelled in parallel, then joined (slab boundaries, periodic faces) by one
//    thread, then numbered: roots get -(1, 2, ...) in memory order, every run start walks up
//    to its root's number, the runs are filled, and a last pass flips the signs.
namespace {

using Label = std::int32_t;
using Word = std::uint64_t;

// A neighbour row (y + dy, z + dz) already visited in memory order, and whether voxels x-1
// and x+1 of that row are neighbours of voxel x too (else only x).
struct RowOffset {
  int dy, dz;
  bool diagonal_x;
};

std::vector<RowOffset> backward_rows(Connectivity c) {
  switch (c) {
    case Connectivity::Faces6: return {{-1, 0, false}, {0, -1, false}};
    case Connectivity::Edges18: return {{-1, 0, true}, {0, -1, true}, {-1, -1, false}, {1, -1, false}};
    case Connectivity::Corners26: return {{-1, 0, true}, {0, -1, true}, {-1, -1, true}, {1, -1, true}};
  }
  return {};
}

// Union-find over voxel indices, stored in the label array: L[i] is i's parent.
struct Forest {
  Label* L;
  Label find(Label i) const {
    while (L[i] != i) {
      const Label g = L[L[i]];
      L[i] = g;  // path halving
      i = g;
    }
    return i;
  }
  // Returns the root that stopped being one, or -1 when a and b were already together.
  Label unite(Label a, Label b) const {
    a = find(a);
    b = find(b);
    if (a == b) return -1;
    if (a < b) std::swap(a, b);
    L[a] = b;
    return a;
  }
};

// Bit x % 64 of word x / 64 is set when m[x] != 0; bits past n are 0.
void row_bits(const std::uint8_t* m, int n, Word* bits) {
  const int words = (n + 63) / 64;
  for (int w = 0; w < words; ++w) {
    const int x0 = 64 * w, len = std::min(64, n - x0);
    Word b = 0;
    int x = 0;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    for (; x + 16 <= len; x += 16) {
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m + x0 + x));
      const unsigned is_zero = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, zero)));
      b |= static_cast<Word>(~is_zero & 0xffffu) << x;
    }
#endif
    for (; x < len; ++x) b |= static_cast<Word>(m[x0 + x] != 0) << x;
    bits[w] = b;
  }
}

// Word w of (a << 1) with the carry from word w-1, and of (a >> 1) with the carry from w+1.
inline Word shl1(const Word* a, int w) { return (a[w] << 1) | (w > 0 ? a[w - 1] >> 63 : 0); }
inline Word shr1(const Word* a, int w, int words) { return (a[w] >> 1) | (w + 1 < words ? a[w + 1] << 63 : 0); }

inline int run_start(const Word* b, int x);

// Unions between a row and one earlier neighbour row: at every voxel x where the pair
// (x, x + dx) is void in (row, neighbour) and the pair (x-1, x-1+dx) is not (which would join
// the same two runs). Returns the number of successful unions.
long unite_rows(const Forest& f, const Word* cur, const Word* nbr, int words, Label base, Label nbase,
                bool diagonal_x) {
  long merged = 0;
  for (int dx = diagonal_x ? -1 : 0; dx <= (diagonal_x ? 1 : 0); ++dx) {
    Word prev = 0;  // the pair word of w-1
    for (int w = 0; w < words; ++w) {
      const Word shifted = dx == 0 ? nbr[w] : dx > 0 ? shr1(nbr, w, words) : shl1(nbr, w);
      const Word c = cur[w] & shifted;
      Word events = c & ~((c << 1) | (prev >> 63));
      prev = c;
      while (events) {
        const int x = 64 * w + std::countr_zero(events);
        events &= events - 1;
        if (f.unite(base + run_start(cur, x), nbase + run_start(nbr, x + dx)) >= 0) ++merged;
      }
    }
  }
  return merged;
}

// Run starts of a row: void voxels whose left neighbour is not void.
inline Word run_starts(const Word* b, int w) { return b[w] & ~shl1(b, w); }

// Position of the first voxel of the run holding the void voxel x of a row of bits.
inline int run_start(const Word* b, int x) {
  int w = x >> 6;
  const int bit = x & 63;
  Word zeros = ~b[w] & (bit == 63 ? ~Word(0) : (Word(2) << bit) - 1);  // solid voxels at or before x
  while (zeros == 0) {
    if (w == 0) return 0;
    zeros = ~b[--w];
  }
  return 64 * w + 64 - std::countl_zero(zeros);
}

}  // namespace

int label_components(const std::uint8_t* image, std::array<int, 3> dims, std::vector<Label>& labels,
                     const LabelOptions& options) {
  const int nx = dims[0], ny = dims[1], nz = dims[2];
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("label_components: dimensions must be >= 1");
  const long long total = 1LL * nx * ny * nz;
  if (total >= 2147483647LL) throw std::invalid_argument("label_components: 2^31 - 1 voxels or more");
  labels.resize(static_cast<std::size_t>(total));
  Label* L = labels.data();
  const Forest forest{L};
  const auto rows = backward_rows(options.connectivity);
  const long plane = 1L * nx * ny;
  const int words = (nx + 63) / 64;
  std::vector<Word> bits(static_cast<std::size_t>(ny) * nz * words);
  auto row_words = [&](int y, int z) { return bits.data() + (static_cast<std::size_t>(z) * ny + y) * words; };

  // Several slabs per thread, handed out dynamically: when another process slows one thread
  // down, the others take its slabs (the numbering does not depend on the slab count).
  const int threads = omp_get_max_threads();
  const int slabs = std::max(1, std::min(threads == 1 ? 1 : 4 * threads, nz));
  std::vector<int> z_begin(slabs + 1);
  for (int t = 0; t <= slabs; ++t) z_begin[t] = static_cast<int>(1LL * nz * t / slabs);
  auto slab_of = [&](Label i) {
    const int z = static_cast<int>(i / plane);
    return static_cast<int>(std::upper_bound(z_begin.begin(), z_begin.end(), z) - z_begin.begin()) - 1;
  };
  std::vector<long> roots(slabs, 0);  // roots per slab

  // 1. Runs and unions inside each slab; unions never leave the slab, so slabs are independent.
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(threads, slabs))
  for (int t = 0; t < slabs; ++t) {
    long runs = 0, merged = 0;
    for (int z = z_begin[t]; z < z_begin[t + 1]; ++z)
      for (int y = 0; y < ny; ++y) {
        const long base = (1L * z * ny + y) * nx;
        const std::uint8_t* m = image + base;
        Label* row = L + base;
        Word* b = row_words(y, z);
        row_bits(m, nx, b);
        // Only run starts are nodes of the forest; the other voxels of a run find their start
        // from the bits when needed (run_start).
        for (int w = 0; w < words; ++w)
          for (Word st = run_starts(b, w); st; st &= st - 1, ++runs) {
            const int x = 64 * w + std::countr_zero(st);
            row[x] = static_cast<Label>(base + x);
          }
        for (const auto& r : rows) {
          const int yy = y + r.dy, zz = z + r.dz;
          if (yy < 0 || yy >= ny || zz < z_begin[t]) continue;
          const long nbase = (1L * zz * ny + yy) * nx;
          merged += unite_rows(forest, b, row_words(yy, zz), words, static_cast<Label>(base),
                               static_cast<Label>(nbase), r.diagonal_x);
        }
      }
    roots[t] = runs - merged;
  }

  // 2. Across slab boundaries and periodic faces, one thread: a lost root is counted off its slab.
  auto unite_counted = [&](Label a, Label b) {
    const Label lost = forest.unite(a, b);
    if (lost >= 0) --roots[slab_of(lost)];
  };
  for (int t = 1; t < slabs; ++t) {
    const int z = z_begin[t];
    for (int y = 0; y < ny; ++y) {
      const long base = (1L * z * ny + y) * nx;
      for (const auto& r : rows) {
        if (r.dz == 0) continue;
        const int yy = y + r.dy, zz = z + r.dz;
        if (yy < 0 || yy >= ny) continue;
        const long nbase = (1L * zz * ny + yy) * nx;
        const std::uint8_t *m = image + base, *nm = image + nbase;
        for (int x = 0; x < nx; ++x) {
          if (!m[x]) continue;
          for (int dx = r.diagonal_x ? -1 : 0; dx <= (r.diagonal_x ? 1 : 0); ++dx) {
            const int xx = x + dx;
            if (xx >= 0 && xx < nx && nm[xx])
              unite_counted(static_cast<Label>(base + run_start(row_words(y, z), x)),
                            static_cast<Label>(nbase + run_start(row_words(yy, zz), xx)));
          }
        }
      }
    }
  }
  // Periodic faces: every voxel p on the face coordinate n_a - 1 of a periodic axis a, and
  // every neighbour offset d with d_a = +1, wrapped along the periodic axes.
  const int conn = static_cast<int>(options.connectivity);
  for (int a = 0; a < 3; ++a) {
    if (!options.periodic[a]) continue;
    std::vector<std::array<int, 3>> offsets;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::array<int, 3> d{dx, dy, dz};
          const int n1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
          if (d[a] != 1) continue;
          if ((conn == 6 && n1 > 1) || (conn == 18 && n1 > 2)) continue;
          offsets.push_back(d);
        }
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int v = 0; v < dims[c]; ++v)
      for (int u = 0; u < dims[b]; ++u) {
        std::array<int, 3> p{};
        p[a] = dims[a] - 1;
        p[b] = u;
        p[c] = v;
        const long ip = p[0] + 1L * nx * (p[1] + 1L * ny * p[2]);
        if (!image[ip]) continue;
        for (const auto& d : offsets) {
          std::array<int, 3> q{};
          bool inside = true;
          for (int k = 0; k < 3; ++k) {
            q[k] = p[k] + d[k];
            if (q[k] < 0 || q[k] >= dims[k]) {
              if (!options.periodic[k]) inside = false;
              q[k] = (q[k] + dims[k]) % dims[k];
            }
          }
          if (!inside) continue;
          const long iq = q[0] + 1L * nx * (q[1] + 1L * ny * q[2]);
          if (image[iq])
            unite_counted(static_cast<Label>(ip - p[0] + run_start(row_words(p[1], p[2]), p[0])),
                          static_cast<Label>(iq - q[0] + run_start(row_words(q[1], q[2]), q[0])));
        }
      }
  }

  // 3. Numbers: roots (always run starts) get -(1, 2, ...) in memory order; slab t starts
  // after the roots of slabs 0..t-1.
  std::vector<long> first(slabs + 1, 0);
  for (int t = 0; t < slabs; ++t) first[t + 1] = first[t] + roots[t];
  const long count = first[slabs];
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(threads, slabs))
  for (int t = 0; t < slabs; ++t) {
    Label next = static_cast<Label>(first[t]);
    for (int z = z_begin[t]; z < z_begin[t + 1]; ++z)
      for (int y = 0; y < ny; ++y) {
        const Word* b = row_words(y, z);
        const long base = (1L * z * ny + y) * nx;
        for (int w = 0; w < words; ++w)
          for (Word s = run_starts(b, w); s; s &= s - 1) {
            const long i = base + 64 * w + std::countr_zero(s);
            if (L[i] == i) L[i] = -(++next);
          }
      }
  }
  // 4. Each run start walks up to its root's number and keeps it (negative); then its run is
  // filled. A parent in an earlier slab may be rewritten by another thread meanwhile, but only
  // to its (negative) number, so the walk ends at the right number; parents are always run
  // starts, so the other voxels are private to their thread. atomic_ref makes the concurrent
  // accesses to run starts defined behaviour (plain moves on x86).
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(threads, slabs))
  for (int t = 0; t < slabs; ++t) {
    for (int z = z_begin[t]; z < z_begin[t + 1]; ++z)
      for (int y = 0; y < ny; ++y) {
        const Word* b = row_words(y, z);
        const long base = (1L * z * ny + y) * nx;
        for (int w = 0; w < words; ++w)
          for (Word s = run_starts(b, w); s; s &= s - 1) {
            const long i = base + 64 * w + std::countr_zero(s);
            Label v = std::atomic_ref<Label>(L[i]).load(std::memory_order_relaxed);
            if (v < 0) continue;
            while ((v = std::atomic_ref<Label>(L[v]).load(std::memory_order_relaxed)) >= 0) {
            }
            std::atomic_ref<Label>(L[i]).store(v, std::memory_order_relaxed);
          }
        Label* row = L + base;
        const std::uint8_t* m = image + base;
        Label cur = 0;
        unsigned previous = 0;
        for (int x = 0; x < nx; ++x) {  // branch-free: a run start rewrites its own number
          const unsigned v = m[x] != 0;
          const Label here = std::atomic_ref<Label>(row[x]).load(std::memory_order_relaxed);
          const Label start = -static_cast<Label>(v & ~previous);
          cur = (here & start) | (cur & ~start);
          previous = v;
          std::atomic_ref<Label>(row[x]).store(cur & -static_cast<Label>(v), std::memory_order_relaxed);
        }
      }
  }
  // 5. Positive numbers.
#pragma omp parallel for schedule(static) num_threads(std::min(threads, slabs))
  for (long i = 0; i < total; ++i) L[i] = -L[i];
  return static_cast<int>(count);
}

}  // namespace cmp::voxel
