// Benchmarks of the soft-sphere machinery (make bench, scripts/bench/15-shellpack.sh):
//   bench_spheres jam N SEEDS [TOL [first]]  time per jammed packing, FIRE iterations per
//                                        second; "first" accepts the first jammed packing
//   bench_spheres fire N PHI TOL SEED [DATA [TABLE]]
//                                        one FIRE minimisation from random centres at volume
//                                        fraction PHI (the LAMMPS comparison); with DATA, the
//                                        start is also written as a LAMMPS data file, and with
//                                        TABLE the Hertz law as a LAMMPS pair_style table file
#include "minimise/fire.hpp"
#include "core/random.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/jamming.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

using namespace cmp;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "jam" && argc >= 4) {
    const int n = std::atoi(argv[2]), seeds = std::atoi(argv[3]);
    spheres::JammingParameters p;
    if (argc > 4) p.fire.force_tolerance = std::atof(argv[4]);
    // "first": time the protocol itself, accepting the first packing whatever its rattlers
    // (rattler-free packings of hundreds of spheres are rare, so rejection would dominate).
    const bool first = argc > 5 && std::string(argv[5]) == "first";
    if (first) p.require_isostatic = false, p.reject_rattlers = false;
    double seconds = 0, phi = 0;
    long iterations = 0, rejected = 0, isostatic = 0;
    for (int s = 1; s <= seeds; ++s) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = spheres::jam_spheres(n, static_cast<std::uint64_t>(s), p);
      seconds += seconds_since(t0);
      iterations += r.fire_iterations;
      rejected += r.rejected_tries;
      phi += r.packing.volume_fraction();
      isostatic += r.contacts == 3 * n - 2;
      if (std::getenv("VERBOSE"))
        fmt::print(stderr, "seed {} phi {:.5f} contacts {} (3N-2 = {}) P {:.3e} maxF {:.2e} tries {} it {}\n", s,
                   r.packing.volume_fraction(), r.contacts, 3 * n - 2, r.pressure, r.max_force, r.rejected_tries + 1,
                   r.fire_iterations);
    }
    fmt::print("jam,{},{},{},{},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.4f},{}\n", n, seeds, p.fire.force_tolerance,
               first ? "first_packing" : "rattler_free_isostatic",
               seconds / seeds, seconds, iterations, iterations * double(n) / seconds, iterations / seconds,
               phi / seeds, double(rejected) / seeds);
    (void)isostatic;
    return 0;
  }
  if (mode == "fire" && argc >= 6) {
    const int n = std::atoi(argv[2]);
    const double phi = std::atof(argv[3]), tol = std::atof(argv[4]);
    const auto seed = static_cast<std::uint64_t>(std::atoll(argv[5]));
    const double side = spheres::jamming_box_side(n);
    const double radius = std::cbrt(3 * phi * side * side * side / (4 * std::numbers::pi * n));
    Random random(seed);
    Eigen::VectorXd x(3L * n);
    for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = side * random.uniform();
    spheres::HertzSpheres system(Eigen::Vector3d::Constant(side), Eigen::VectorXd::Constant(n, radius), {});
    if (argc > 6) {  // the same start for LAMMPS
      std::FILE* f = std::fopen(argv[6], "w");
      fmt::print(f, "LAMMPS data file: bench_spheres fire {} {} seed {}\n\n{} atoms\n1 atom types\n\n", n, phi, seed, n);
      for (const char* axis : {"x", "y", "z"}) fmt::print(f, "0 {:.17g} {}lo {}hi\n", side, axis, axis);
      fmt::print(f, "\nMasses\n\n1 1\n\nAtoms # atomic\n\n");
      for (int i = 0; i < n; ++i) fmt::print(f, "{} 1 {:.17g} {:.17g} {:.17g}\n", i + 1, x[3 * i], x[3 * i + 1], x[3 * i + 2]);
      std::fclose(f);
    }
    if (argc > 7) {  // Hertz energy and force on a fine table, r from 1e-4 d to d
      std::FILE* f = std::fopen(argv[7], "w");
      const int points = 100000;
      const double d = 2 * radius, c = cmp::hertz_prefactor({}, radius, radius);
      fmt::print(f, "# Hertz, E = 1, nu = 0.5, d = {:.17g}\n\nHERTZ\nN {} R {:.17g} {:.17g}\n\n", d, points, 1e-4 * d, d);
      for (int k = 0; k < points; ++k) {
        const double r = 1e-4 * d + (d - 1e-4 * d) * k / (points - 1), h = d - r;
        fmt::print(f, "{} {:.17g} {:.17g} {:.17g}\n", k + 1, r, cmp::hertz_energy(c, h), cmp::hertz_force(c, h));
      }
      std::fclose(f);
    }
    minimise::FireParameters p;
    p.force_tolerance = tol;
    p.max_iterations = 10'000'000;
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = minimise::fire(x, [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) { system.forces(y, f); }, p);
    const double s = seconds_since(t0);
    const auto state = system.evaluate(x);
    fmt::print("fire,{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g}\n", n, phi, tol, minimise::fire_stop_name(r.stop),
               r.iterations, s, r.iterations * double(n) / s, state.energy, r.max_force);
    return 0;
  }
  fmt::print(stderr, "usage: bench_spheres jam N SEEDS [TOL [first]] | fire N PHI TOL SEED [DATA [TABLE]]\n");
  return 2;
}
