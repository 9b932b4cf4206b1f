// Benchmarks of rndmesh's two stages, one CSV row per measurement on stdout:
//   bench_spheremesh anneal N [anneals sweeps [T_max T_min]]   Monte Carlo (thesis schedule)
//   bench_spheremesh delaunay N                   spherical Delaunay of N random points
#include "core/version.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

using namespace cmp;

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: bench_spheremesh anneal|delaunay N [anneals sweeps]\n");
    return 2;
  }
  const std::string what = argv[1];
  const int n = std::atoi(argv[2]);
  if (what == "anneal") {
    spheremesh::AnnealingParameters p;
    p.points = n;
    p.radius = 1;
    if (argc > 4) p.anneals = std::atoi(argv[3]), p.sweeps_per_anneal = std::atoi(argv[4]);
    if (argc > 6) p.t_max = std::atof(argv[5]), p.t_min = std::atof(argv[6]);
    const auto r = spheremesh::anneal_on_sphere(p);
    fmt::print("anneal,{},{},{},{},{},{:.4f},{:.4g},{:.4g},{:.4f}\n", n, p.anneals, p.sweeps_per_anneal, p.t_max, p.t_min, r.seconds,
               r.attempted / r.seconds, r.seconds / (static_cast<double>(p.anneals) * p.sweeps_per_anneal) / n * 1e9,
               static_cast<double>(r.accepted) / r.attempted);
  } else if (what == "delaunay") {
    const auto points = spheremesh::random_points_on_sphere(n, 1.0, 1);
    const auto start = std::chrono::steady_clock::now();
    const auto faces = spheremesh::spherical_delaunay(points);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("delaunay,{},{},{:.4f},{:.4g}\n", n, faces.rows(), seconds, n / seconds);
  } else {
    return 2;
  }
  return 0;
}
