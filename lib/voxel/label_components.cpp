#include "voxel/label_components.hpp"

#include "core/errors.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace cmp::voxel {

Connectivity connectivity_from_name(const std::string& name) {
  if (name == "6") return Connectivity::Faces6;
  if (name == "18") return Connectivity::Edges18;
  if (name == "26") return Connectivity::Corners26;
  throw UsageError("--connectivity must be 6, 18 or 26, got '" + name + "'");
}

namespace {

using Label = std::int32_t;

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

// Union-find over voxel indices, stored in the label array: L[i] is i's parent, a root is
// its own parent, and a union links the larger root under the smaller one. So every root is
// the first voxel (in memory order) of its set, whatever the order of the unions.
struct Forest {
  Label* L;
  Label find(Label i) const {
    while (L[i] != i) {
      const Label p = L[i], g = L[p];
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

// Unions between row (y, z) and one earlier neighbour row, run by run: a pair already implied
// by the previous voxel of both rows is skipped. Returns the number of successful unions.
inline long unite_rows(const Forest& f, const std::uint8_t* m, const Label* L, const std::uint8_t* nm,
                       const Label* nL, int nx, bool diagonal_x) {
  long merged = 0;
  for (int x = 0; x < nx; ++x) {
    if (!m[x]) continue;
    if (nm[x]) {
      if (x == 0 || !(m[x - 1] && nm[x - 1]))
        if (f.unite(L[x], nL[x]) >= 0) ++merged;
    } else if (diagonal_x) {
      if (x > 0 && nm[x - 1] && f.unite(L[x], nL[x - 1]) >= 0) ++merged;
      if (x + 1 < nx && nm[x + 1] && f.unite(L[x], nL[x + 1]) >= 0) ++merged;
    }
  }
  return merged;
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

  const int slabs = std::max(1, std::min(omp_get_max_threads(), nz));
  std::vector<int> z_begin(slabs + 1);
  for (int t = 0; t <= slabs; ++t) z_begin[t] = static_cast<int>(1LL * nz * t / slabs);
  auto slab_of = [&](Label i) {
    const int z = static_cast<int>(i / plane);
    return static_cast<int>(std::upper_bound(z_begin.begin(), z_begin.end(), z) - z_begin.begin()) - 1;
  };
  std::vector<long> roots(slabs, 0);  // roots per slab

  // 1. Runs and unions inside each slab; unions never leave the slab, so slabs are independent.
#pragma omp parallel for schedule(static, 1) num_threads(slabs)
  for (int t = 0; t < slabs; ++t) {
    long runs = 0, merged = 0;
    for (int z = z_begin[t]; z < z_begin[t + 1]; ++z)
      for (int y = 0; y < ny; ++y) {
        const long base = (1L * z * ny + y) * nx;
        const std::uint8_t* m = image + base;
        Label* row = L + base;
        for (int x = 0; x < nx;) {
          if (!m[x]) {
            ++x;
            continue;
          }
          const Label start = static_cast<Label>(base + x);
          ++runs;
          while (x < nx && m[x]) row[x++] = start;
        }
        for (const auto& r : rows) {
          const int yy = y + r.dy, zz = z + r.dz;
          if (yy < 0 || yy >= ny || zz < z_begin[t]) continue;
          const long nbase = (1L * zz * ny + yy) * nx;
          merged += unite_rows(forest, m, row, image + nbase, L + nbase, nx, r.diagonal_x);
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
            if (xx >= 0 && xx < nx && nm[xx]) unite_counted(L[base + x], L[nbase + xx]);
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
          if (image[iq]) unite_counted(L[ip], L[iq]);
        }
      }
  }

  // 3. Numbers: roots get -(1, 2, ...) in memory order; slab t starts after the roots of
  // slabs 0..t-1.
  std::vector<long> first(slabs + 1, 0);
  for (int t = 0; t < slabs; ++t) first[t + 1] = first[t] + roots[t];
  const long count = first[slabs];
#pragma omp parallel for schedule(static, 1) num_threads(slabs)
  for (int t = 0; t < slabs; ++t) {
    Label next = static_cast<Label>(first[t]);
    const long end = plane * z_begin[t + 1];
    for (long i = plane * z_begin[t]; i < end; ++i)
      if (image[i] && L[i] == i) L[i] = -(++next);
  }
  // 4. Every other voxel takes its root's number. A parent in an earlier slab may be rewritten
  // by its own thread meanwhile, but only ever to another ancestor or to the (negative) number,
  // so the walk ends at the right number; atomic_ref makes those concurrent accesses defined.
#pragma omp parallel for schedule(static, 1) num_threads(slabs)
  for (int t = 0; t < slabs; ++t) {
    const long begin = plane * z_begin[t], end = plane * z_begin[t + 1];
    for (long i = begin; i < end; ++i) {
      if (!image[i]) {
        L[i] = 0;
        continue;
      }
      Label v = L[i];
      if (v < 0) continue;
      if (v >= begin && L[v] < 0) {  // the common case: the run start, already numbered
        L[i] = L[v];
        continue;
      }
      while ((v = std::atomic_ref<Label>(L[v]).load(std::memory_order_relaxed)) >= 0) {
      }
      std::atomic_ref<Label>(L[i]).store(v, std::memory_order_relaxed);
    }
  }
  // 5. Positive numbers.
#pragma omp parallel for schedule(static) num_threads(slabs)
  for (long i = 0; i < total; ++i) L[i] = -L[i];
  return static_cast<int>(count);
}

}  // namespace cmp::voxel
