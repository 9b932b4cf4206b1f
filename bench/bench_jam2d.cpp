// Growth-driven jamming of budding cells (jam2d grow): wall time and minimisation work to the
// jamming point of thesis 3.4.2, one colony per seed on one thread.
//   bench_jam2d BOX SEED_FIRST SEED_LAST [double]  ->  one CSV line per seed (no header):
//   box,seed,cells,phi_J,Z,f_u,seconds,fire_iterations,accepted,rejected
#include "cells2d/colony.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace cmp::cells2d;

int main(int argc, char** argv) {
  const double box = argc > 1 ? std::atof(argv[1]) : 8;
  const long first = argc > 2 ? std::atol(argv[2]) : 1, last = argc > 3 ? std::atol(argv[3]) : first;
  for (long seed = first; seed <= last; ++seed) {
    GrowthParameters p;
    p.box = box;
    p.reset_step = !(argc > 4 && std::string(argv[4]) == "double");
    const auto t0 = std::chrono::steady_clock::now();
    Colony colony(p, static_cast<std::uint64_t>(seed));
    colony.grow_to_jamming();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const PackingAnalysis a = colony.analyse();
    std::printf("%g,%ld,%d,%.6f,%.4f,%.4f,%.3f,%ld,%ld,%ld\n", box, seed, a.cells, colony.phi_jamming(), a.Z, a.f_u, s,
                colony.counters().iterations, colony.counters().accepted, colony.counters().rejected);
    std::fflush(stdout);
  }
}
