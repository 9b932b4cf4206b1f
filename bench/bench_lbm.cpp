// lbflow's lattice Boltzmann core for make bench and the README's validation table:
//   bench_lbm speed N THREADS [STYLE] [STEPS] [double|float]
//                                              MLUPS of a dense N^3 periodic box and of a porous
//                                              N^3 box (random overlapping spheres, porosity ~0.35),
//                                              beside a STREAM-style triad measured just before and
//                                              after each (the higher) and the two bounds it gives
//                                              (304 bytes per update, and the bytes the solver
//                                              moves, links included),
//                                              and of the even and odd AA steps alone
//   bench_lbm triad THREADS                    the triad alone: GB/s and the MLUPS bounds of a
//                                              double D3Q19 update, 304 and 340 bytes
//                                              (scripts/bench/40-lbflow_run.sh puts them beside lbflow's runs)
//   bench_lbm sphere-array [N...]              kappa of the simple cubic sphere array against
//                                              Zick & Homsy (1982) for several solid fractions and
//                                              resolutions, half-way vs interpolated bounce-back
// Each prints CSV with a header line.
#include "lbm/flow_solver.hpp"
#include "lbm/huge_pages.hpp"
#include "lbm/sphere_lattice.hpp"
#include "lbm/steady_state.hpp"

#include "core/random.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

using namespace cmp;
using namespace cmp::lbm;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// One thread's share of the triad a = b + 3 c, compiled for AVX-512 too (the sweep's own
// instruction set on such a processor; picked when the program loads).
[[gnu::target_clones("arch=x86-64-v4", "default")]] void triad_range(double* __restrict a, const double* __restrict b,
                                                                     const double* __restrict c, long begin, long end) {
  for (long i = begin; i < end; ++i) a[i] = b[i] + 3 * c[i];
}

// STREAM triad a = b + 3 c on `threads` threads, static partition; best of 10, GB/s counting
// 24 bytes per element (as STREAM does; write-allocate traffic not counted). The arrays come
// from the solver's own allocator (2 MB huge pages where the kernel grants them): with 4 kB
// pages the same loop read 47-64 GB/s from one run to the next on this machine, with huge
// pages 67-75, so a bound from small pages flattered the solver.
double triad_gbs(int threads) {
  const long n = 1L << 25;
  BigVector<double> a(n), b(n), c(n);
  omp_set_num_threads(threads);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    a[i] = 0;
    b[i] = 1;
    c[i] = 2;
  }
  double best = 1e30;
  for (int rep = 0; rep < 10; ++rep) {
    const double t0 = now();
#pragma omp parallel
    {
      const long t = omp_get_thread_num(), nt = omp_get_num_threads();
      triad_range(a.data(), b.data(), c.data(), n * t / nt, n * (t + 1) / nt);
    }
    best = std::min(best, now() - t0);
  }
  volatile double sink = a[n / 2];
  (void)sink;
  return 24.0 * n / best / 1e9;
}

// The MLUPS bound at bandwidth bw GB/s of an update that moves `bytes`: 2 x 19 x 8 = 304 for
// the double populations alone (the floor), update_bytes() or
// FlowSolver::bytes_moved_per_update() with the link table's bytes (340 in double).
double bound_mlups(double bw, double bytes = 2 * 19 * 8) { return bw * 1e9 / bytes / 1e6; }

int speed(int n, int threads, const std::string& style, long steps, bool f32) {
  std::printf("case,N,porosity,threads,collision,fluid_nodes,steps,seconds,mlups,bytes_per_node,triad_gbs,bound_mlups,fraction_of_bound,even_mlups,odd_mlups,precision,update_bytes,bound_with_links_mlups,fraction_with_links\n");
  for (int porous = 0; porous < 2; ++porous) {
    // The triad just before the case and just after it, the higher counted: this machine's
    // bandwidth moved between 40 and 75 GB/s within an hour while the kernel's MLUPS did not,
    // so a bound from one triad alone could fall in a dip.
    const double bw_before = triad_gbs(threads);
    const PoreLattice p = porous ? random_sphere_box(n, 0.35, 2026) : open_box(n, n, n);
    FlowSettings s;
    s.collision = style;
    s.driving = porous ? Driving::kPressure : Driving::kBodyForce;
    s.precision = f32 ? Precision::kFloat : Precision::kDouble;
    omp_set_num_threads(threads);
    FlowSolver solver(p, s);
    solver.step(2);  // first touch, warm-up
    double best = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
      const double t0 = now();
      solver.step(steps);
      best = std::min(best, now() - t0);
    }
    const double mlups = solver.fluid_nodes() * static_cast<double>(steps) / best / 1e6;
    // Each AA parity alone (best of 5 single steps): even steps stream a node's own block,
    // odd steps go to the neighbours.
    double parity_best[2] = {1e30, 1e30};
    for (int rep = 0; rep < 10; ++rep) {
      const int parity = static_cast<int>(solver.steps() & 1);
      const double t0 = now();
      solver.step(1);
      parity_best[parity] = std::min(parity_best[parity], now() - t0);
    }
    const double parity_mlups[2] = {solver.fluid_nodes() / parity_best[0] / 1e6, solver.fluid_nodes() / parity_best[1] / 1e6};
    const double bw = std::max(bw_before, triad_gbs(threads));
    const double bound = bound_mlups(bw), own = bound_mlups(bw, solver.bytes_moved_per_update());
    std::printf("%s,%d,%.4f,%d,%s,%ld,%ld,%.4f,%.2f,%.1f,%.2f,%.1f,%.3f,%.2f,%.2f,%s,%.1f,%.1f,%.3f\n", porous ? "porous" : "dense", n,
                p.porosity(), threads, style.c_str(), solver.fluid_nodes(), steps, best, mlups, solver.bytes_per_fluid_node(), bw,
                bound, mlups / bound, parity_mlups[0], parity_mlups[1], f32 ? "float" : "double", solver.bytes_moved_per_update(), own,
                mlups / own);
  }
  return 0;
}

int sphere_array(const std::vector<int>& sizes) {
  std::printf("solid_fraction,K_zick_homsy,N,radius,kappa_ref,kappa_halfway,err_halfway,kappa_interpolated,err_interpolated,steps\n");
  for (const DragReference& ref : zick_homsy_simple_cubic()) {
    for (int n : sizes) {
      const double a = n * std::cbrt(3 * ref.solid_fraction / (4 * std::numbers::pi));
      const double kref = sphere_array_kappa(n, ref.solid_fraction, ref.K);
      double kappa[2];
      long steps = 0;
      for (int interp = 0; interp < 2; ++interp) {
        PoreLattice p = simple_cubic_array(n, ref.solid_fraction);
        if (!interp) p.wall_fraction = nullptr;
        FlowSettings s;
        s.driving = Driving::kBodyForce;
        const SteadyStateResult r = solve_steady(p, s, {1e-6, 50, 4, 200000});
        kappa[interp] = r.final.kappa_lu;
        steps = std::max(steps, r.final.steps);
      }
      std::printf("%.4f,%.3f,%d,%.3f,%.5g,%.5g,%+.4f,%.5g,%+.4f,%ld\n", ref.solid_fraction, ref.K, n, a, kref, kappa[0],
                  kappa[0] / kref - 1, kappa[1], kappa[1] / kref - 1, steps);
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "speed" && argc >= 4)
    return speed(std::atoi(argv[2]), std::atoi(argv[3]), argc > 4 ? argv[4] : "mrt", argc > 5 ? std::atol(argv[5]) : 20,
                 argc > 6 && std::string(argv[6]) == "float");
  if (mode == "triad" && argc == 3) {
    const double bw = triad_gbs(std::atoi(argv[2]));
    std::printf("triad_gbs,bound_mlups,bound_with_links_mlups\n%.2f,%.1f,%.1f\n", bw, bound_mlups(bw), bound_mlups(bw, update_bytes(Precision::kDouble)));
    return 0;
  }
  if (mode == "sphere-array") {
    std::vector<int> sizes;
    for (int i = 2; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
    if (sizes.empty()) sizes = {16, 24, 32};
    return sphere_array(sizes);
  }
  std::fprintf(stderr, "usage: bench_lbm speed N THREADS [STYLE] [STEPS] [double|float] | triad THREADS | sphere-array [N...]\n");
  return 2;
}
