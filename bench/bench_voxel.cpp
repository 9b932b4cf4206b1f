// percolate's hot loops for make bench (scripts/bench/30-percolate.sh):
//   bench_voxel label N POROSITY THREADS [IMAGE.u8]    random N^3 image (void with probability POROSITY)
//   bench_voxel packing N THREADS [IMAGE.u8]           pore space of 64 shells (642 vertices each) on
//                                                      a 4x4x4 lattice, voxelised on N^3
//   bench_voxel voxelise THREADS                       50 shells of 2562 vertices, delta = 0.03 D0
// label/packing print one CSV row: image, N, porosity, threads, voxels, components, best-of-3
// seconds, million voxels labelled per second, peak RSS [MB] and bytes per voxel; with IMAGE
// the image is also written as raw bytes (x fastest) for scipy to label the same voxels.
#include "core/random.hpp"
#include "spheremesh/subdivision.hpp"
#include "voxel/grid.hpp"
#include "voxel/label_components.hpp"
#include "voxel/porosity.hpp"
#include "voxel/solid_marking.hpp"

#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace cmp;
using namespace cmp::voxel;

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// K^3 shells (icosahedral level `level`, diameter 0.98) on a lattice of spacing 1, jittered.
mesh::TriMesh shell_lattice(std::array<int, 3> k, int level, std::uint64_t seed) {
  const auto s = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, 0.49);
  const long n = k[0] * k[1] * k[2], nv = s.V.rows(), nf = s.F.rows();
  mesh::TriMesh m;
  m.V.resize(n * nv, 3);
  m.F.resize(n * nf, 3);
  Random r(seed);
  long c = 0;
  for (int i = 0; i < k[0]; ++i)
    for (int j = 0; j < k[1]; ++j)
      for (int l = 0; l < k[2]; ++l, ++c) {
        const Eigen::RowVector3d centre(i + 0.5 + r.uniform(-0.005, 0.005), j + 0.5 + r.uniform(-0.005, 0.005),
                                        l + 0.5 + r.uniform(-0.005, 0.005));
        m.V.middleRows(c * nv, nv) = s.V.rowwise() + centre;
        m.F.middleRows(c * nf, nf) = s.F.array() + static_cast<int>(c * nv);
      }
  return m;
}

void label_row(const char* image, int n, double porosity, int threads, const std::vector<std::uint8_t>& img,
               const char* dump) {
  if (dump) std::ofstream(dump, std::ios::binary).write(reinterpret_cast<const char*>(img.data()), img.size());
  omp_set_num_threads(threads);
  std::vector<std::int32_t> labels;
  int count = label_components(img.data(), {n, n, n}, labels);  // warm-up: pages of the labels
  double best = 1e30;
  for (int rep = 0; rep < 3; ++rep) {
    const double t = now();
    count = label_components(img.data(), {n, n, n}, labels);
    best = std::min(best, now() - t);
  }
  const double voxels = static_cast<double>(img.size());
  std::printf("%s,%d,%.4f,%d,%.0f,%d,%.4f,%.1f,%.1f,%.2f\n", image, n, porosity, threads, voxels, count, best,
              voxels / best / 1e6, peak_rss_mb(), peak_rss_mb() * 1048576.0 / voxels);
}
}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "";
  if (what == "label" && argc >= 5) {
    const int n = std::atoi(argv[2]);
    const double p = std::atof(argv[3]);
    std::vector<std::uint8_t> img(static_cast<std::size_t>(n) * n * n);
    Random r(12345);
    for (auto& v : img) v = r.uniform() < p;
    label_row("random", n, p, std::atoi(argv[4]), img, argc > 5 ? argv[5] : nullptr);
    return 0;
  }
  if (what == "packing" && argc >= 4) {
    const int n = std::atoi(argv[2]);
    const auto m = shell_lattice({4, 4, 4}, 4, 7);
    const auto g = make_grid(Eigen::Vector3d::Constant(4.0), 4.0 / n);
    std::vector<std::uint8_t> img(g.size(), 1);
    mark_shells(m.V, m.F, g, ShellMarking::Triangles, 0.0, img);
    label_row("packing", n, voxel_porosity(img), std::atoi(argv[3]), img, argc > 4 ? argv[4] : nullptr);
    return 0;
  }
  if (what == "voxelise" && argc >= 3) {
    const int threads = std::atoi(argv[2]);
    omp_set_num_threads(threads);
    const auto m = shell_lattice({5, 5, 2}, 5, 7);  // 50 shells x 2562 vertices, D0 = 1 (0.98)
    const auto g = make_grid(Eigen::Vector3d(5, 5, 2), 0.03);
    double best = 1e30;
    std::vector<std::uint8_t> img;
    for (int rep = 0; rep < 3; ++rep) {
      img.assign(g.size(), 1);
      const double t = now();
      mark_shells(m.V, m.F, g, ShellMarking::Triangles, 0.0, img);
      best = std::min(best, now() - t);
    }
    double best_v = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
      img.assign(g.size(), 1);
      const double t = now();
      mark_shells(m.V, m.F, g, ShellMarking::Vertices, 0.0, img);
      best_v = std::min(best_v, now() - t);
    }
    std::printf("%d,%ld,%ld,%.3f,%d,%d,%d,%d,%.4f,%.4f,%.1f\n", 50, static_cast<long>(m.V.rows() / 50),
                static_cast<long>(m.F.rows()), 0.03, g.dims[0], g.dims[1], g.dims[2], threads, best, best_v,
                peak_rss_mb());
    return 0;
  }
  std::fprintf(stderr, "usage: bench_voxel label N POROSITY THREADS [IMAGE.u8] | packing N THREADS [IMAGE.u8] | "
                       "voxelise THREADS\n");
  return 2;
}
