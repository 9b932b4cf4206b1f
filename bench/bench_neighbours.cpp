// Timing of the neighbour list on 100k random points at the density of a jammed sphere
// packing (diameter 1, phi = 0.64, cutoff 1, skin 0.1, periodic cube), for make bench.
// Prints one CSV row per (particle order, threads): build and force-loop times (best of 10).
#include "neighbours/neighbour_list.hpp"
#include "neighbours/cell_grid.hpp"
#include "core/random.hpp"
#include <omp.h>
#include <chrono>
#include <cstdio>
#include <algorithm>
using namespace cmp::neighbours;
using cmp::mesh::VertexMatrix;
static double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
int main(int argc, char** argv) {
  const int n = 100000;
  const double phi = 0.64, rho = phi / (M_PI / 6), L = std::cbrt(n / rho);
  Box box; box.lengths.setConstant(L); box.periodic = {true, true, true};
  cmp::Random r(1);
  VertexMatrix X(n, 3);
  for (int i = 0; i < n; ++i) for (int a = 0; a < 3; ++a) X(i, a) = L * r.uniform();
  std::printf("order,N,threads,build_ms,pairs_per_particle,force_loop_ms,needs_rebuild_ms\n");
  for (bool sorted : {false, true}) {
    if (sorted) {  // particles renumbered in cell order, as a simulation may do once in a while
      CellGrid g(box, 1.1); g.build(X);
      VertexMatrix Y(n, 3);
      for (int k = 0; k < n; ++k) Y.row(k) = X.row(g.sorted_indices()[k]);
      X = Y;
    }
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      NeighbourList list(box, 1.0, 0.1);
      list.build(X);  // warm-up (allocations)
      const int reps = 10;
      double best = 1e9;
      for (int k = 0; k < reps; ++k) { double t = now(); list.build(X); best = std::min(best, now() - t); }
      // a force loop over the list
      VertexMatrix Fo = VertexMatrix::Zero(n, 3);
      double bestf = 1e9;
      for (int k = 0; k < reps; ++k) {
        double t = now();
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; ++i) {
          Eigen::Vector3d f = Eigen::Vector3d::Zero();
          for (int j : list.neighbours_of(i)) {
            const Eigen::Vector3d d = list.minimum_image((X.row(i) - X.row(j)).transpose());
            const double r2 = d.squaredNorm();
            if (r2 < 1.0) { const double rr = std::sqrt(r2); f += (1 - rr) / rr * d; }
          }
          Fo.row(i) = f.transpose();
        }
        bestf = std::min(bestf, now() - t);
      }
      double bestr = 1e9;
      for (int k = 0; k < reps; ++k) { double t = now(); volatile bool b = list.needs_rebuild(X); (void)b; bestr = std::min(bestr, now() - t); }
      std::printf("%s,%d,%d,%.3f,%.3f,%.3f,%.4f\n", sorted ? "cell-ordered" : "random-order", n, threads, best * 1e3,
                  2.0 * list.pair_count() / n, bestf * 1e3, bestr * 1e3);
    }
  }
}
