#include "voxel/solid_marking.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"
#include "voxel/triangle_box_overlap.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace cmp::voxel {

ShellMarking shell_marking_from_name(const std::string& name) {
  if (name == "vertices") return ShellMarking::Vertices;
  if (name == "triangles") return ShellMarking::Triangles;
  throw UsageError("--marking must be 'vertices' or 'triangles', got '" + name + "'");
}
std::string shell_marking_name(ShellMarking m) { return m == ShellMarking::Vertices ? "vertices" : "triangles"; }

SphereMarking sphere_marking_from_name(const std::string& name) {
  if (name == "overlap") return SphereMarking::Overlap;
  if (name == "centre" || name == "center") return SphereMarking::Centre;
  throw UsageError("--sphere-marking must be 'overlap' or 'centre', got '" + name + "'");
}
std::string sphere_marking_name(SphereMarking m) { return m == SphereMarking::Overlap ? "overlap" : "centre"; }

namespace {

// Voxel indices [first, last] along axis a of the interval [lo, hi] (unwrapped, so along a
// periodic axis the range may be longer than the axis and visit a voxel in several images), or
// an empty range (first > last) when a non-periodic axis misses it.
struct Range {
  long first, last;
};
Range voxel_range(const VoxelGrid& g, int a, double lo, double hi) {
  const double h = g.spacing[a];
  long first = static_cast<long>(std::floor(lo / h)), last = static_cast<long>(std::floor(hi / h));
  if (!g.periodic[a]) {
    first = std::max(first, 0L);
    last = std::min(last, static_cast<long>(g.dims[a]) - 1);
  }
  return {first, last};
}

inline int wrap(long i, int n) {
  long r = i % n;
  return static_cast<int>(r < 0 ? r + n : r);
}

inline void set_solid(std::vector<std::uint8_t>& pore, std::size_t i) {
  std::atomic_ref<std::uint8_t>(pore[i]).store(0, std::memory_order_relaxed);
}

// Calls f(ix, iy, iz, centre) for every voxel image meeting the box [lo, hi], with (ix, iy, iz)
// wrapped into the grid and centre the centre of that image of the voxel (unwrapped). A box
// longer than a periodic axis visits a voxel once per image it meets, so an element of any
// size is tested against every image of the voxels it may touch.
template <class F>
void for_voxels(const VoxelGrid& g, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, F&& f) {
  Range r[3];
  for (int a = 0; a < 3; ++a) {
    r[a] = voxel_range(g, a, lo[a], hi[a]);
    if (r[a].first > r[a].last) return;
  }
  const Eigen::Vector3d& h = g.spacing;
  for (long k = r[2].first; k <= r[2].last; ++k)
    for (long j = r[1].first; j <= r[1].last; ++j)
      for (long i = r[0].first; i <= r[0].last; ++i) {
        const Eigen::Vector3d c((i + 0.5) * h[0], (j + 0.5) * h[1], (k + 0.5) * h[2]);
        f(wrap(i, g.dims[0]), wrap(j, g.dims[1]), wrap(k, g.dims[2]), c);
      }
}

}  // namespace

void mark_shells(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const VoxelGrid& g, ShellMarking method,
                 double thickness, std::vector<std::uint8_t>& pore) {
  const Eigen::Vector3d half = 0.5 * g.spacing + Eigen::Vector3d::Constant(thickness);
  if (method == ShellMarking::Vertices) {
    const long n = V.rows();
#pragma omp parallel for schedule(static)
    for (long v = 0; v < n; ++v) {
      const Eigen::Vector3d p = V.row(v).transpose();
      if (thickness == 0) {
        // the voxel holding p (a point exactly on a face goes to the upper voxel)
        std::array<long, 3> idx{};
        bool inside = true;
        for (int a = 0; a < 3; ++a) {
          idx[a] = static_cast<long>(std::floor(p[a] / g.spacing[a]));
          if (g.periodic[a]) idx[a] = wrap(idx[a], g.dims[a]);
          else if (idx[a] < 0 || idx[a] >= g.dims[a]) inside = false;
        }
        if (inside) set_solid(pore, g.index(idx[0], idx[1], idx[2]));
      } else {
        const Eigen::Vector3d t = Eigen::Vector3d::Constant(thickness);
        for_voxels(g, p - t, p + t, [&](int i, int j, int k, const Eigen::Vector3d&) { set_solid(pore, g.index(i, j, k)); });
      }
    }
    return;
  }
  const long nf = F.rows();
#pragma omp parallel for schedule(dynamic, 256)
  for (long f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(),
                          c = V.row(F(f, 2)).transpose();
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - thickness,
                          hi = a.cwiseMax(b).cwiseMax(c).array() + thickness;
    for_voxels(g, lo, hi, [&](int i, int j, int k, const Eigen::Vector3d& centre) {
      const std::size_t idx = g.index(i, j, k);
      if (std::atomic_ref<std::uint8_t>(pore[idx]).load(std::memory_order_relaxed) &&  // skip voxels already solid
          triangle_box_overlap(a, b, c, centre, half))
        set_solid(pore, idx);
    });
  }
}

namespace {

// The voxels along one axis within `extent` of the coordinate p, with the signed offset of each
// voxel centre from p: the nearest image along a periodic axis (cmp::minimum_image), so a
// voxel is listed once whatever the extent, at its distance from the nearest image of p.
struct AxisVoxels {
  std::vector<int> index;
  std::vector<double> offset;
};
void axis_voxels(const VoxelGrid& g, int a, double p, double extent, AxisVoxels& out) {
  out.index.clear();
  out.offset.clear();
  const double h = g.spacing[a], L = g.box[a];
  const int n = g.dims[a];
  Range r = voxel_range(g, a, p - extent, p + extent);
  if (g.periodic[a] && r.last - r.first + 1 >= n) r = {0, n - 1};  // every voxel, once
  for (long i = r.first; i <= r.last; ++i) {
    const int w = g.periodic[a] ? wrap(i, n) : static_cast<int>(i);
    const double d = (w + 0.5) * h - p;
    out.index.push_back(w);
    out.offset.push_back(g.periodic[a] ? minimum_image(d, L) : d);
  }
}

}  // namespace

void mark_spheres(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const VoxelGrid& g,
                  SphereMarking method, std::vector<std::uint8_t>& pore) {
  const long n = centres.rows();
#pragma omp parallel
  {
    AxisVoxels ax[3];
    std::vector<double> d2[3];  // squared distance along each axis from the nearest point (Overlap) or the centre
#pragma omp for schedule(dynamic, 16)
    for (long s = 0; s < n; ++s) {
      const double r = radii[s], r2 = r * r;
      for (int a = 0; a < 3; ++a) {
        axis_voxels(g, a, centres(s, a), r, ax[a]);
        d2[a].resize(ax[a].offset.size());
        for (std::size_t i = 0; i < d2[a].size(); ++i) {
          double d = std::abs(ax[a].offset[i]);
          if (method == SphereMarking::Overlap) d = std::max(0.0, d - 0.5 * g.spacing[a]);  // nearest point of the voxel
          d2[a][i] = d * d;
        }
      }
      for (std::size_t k = 0; k < d2[2].size(); ++k) {
        if (d2[2][k] >= r2) continue;
        for (std::size_t j = 0; j < d2[1].size(); ++j) {
          const double djk = d2[2][k] + d2[1][j];
          if (djk >= r2) continue;
          for (std::size_t i = 0; i < d2[0].size(); ++i)
            if (djk + d2[0][i] < r2) set_solid(pore, g.index(ax[0].index[i], ax[1].index[j], ax[2].index[k]));
        }
      }
    }
  }
}

}  // namespace cmp::voxel
