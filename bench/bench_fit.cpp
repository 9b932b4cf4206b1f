// kcfit speed: fits per second of the permeability law (Eq. 5.8, log loss, 120 points) from
// the model's starting grid and from one starting point, and the wall time of a 1000-replica
// bootstrap on 1 and 2 threads.
//   bench_fit            CSV rows: stage,model,points,threads,fits,seconds,fits_per_s
//   bench_fit data       the 120 points, as CSV (for timing scipy on the same data)
#include "core/random.hpp"
#include "fit/bootstrap.hpp"
#include "fit/fit.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace cmp;

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

int main(int argc, char** argv) {
  const auto& m = fit::find_model("kc-percolation");
  Random rng(2026);
  std::vector<double> x, y;
  const double truth[] = {50, 0.146, 0.83};
  for (int i = 0; i < 120; ++i) {
    x.push_back(rng.uniform(0.16, 0.45));
    y.push_back(m.value(x.back(), truth) * std::exp(0.15 * rng.normal()));
  }
  if (argc > 1 && std::strcmp(argv[1], "data") == 0) {
    std::printf("porosity,permeability\n");
    for (std::size_t i = 0; i < x.size(); ++i) std::printf("%.17g,%.17g\n", x[i], y[i]);
    return 0;
  }
  fit::FitOptions o;
  o.loss = fit::Loss::Log;
  auto row = [&](const char* stage, int threads, int fits, double seconds) {
    std::printf("%s,%s,%zu,%d,%d,%.6f,%.1f\n", stage, m.name.c_str(), x.size(), threads, fits, seconds, fits / seconds);
  };
  // Full fit: every starting point of the model's grid.
  fit::FitResult best;
  int fits = 0;
  double t0 = now();
  while (now() - t0 < 1.0 || fits < 10) best = fit::fit(m, x, y, o), ++fits;
  row("fit_multistart", 1, fits, now() - t0);
  // One start, (C, phi_c, gamma) = (40, 0.14, 1), as scripts/bench/kcfit_scipy.py gives curve_fit.
  fit::FitOptions one = o;
  one.start = {40, 0.14, 1.0};
  fits = 0;
  t0 = now();
  while (now() - t0 < 1.0 || fits < 10) fit::fit(m, x, y, one), ++fits;
  row("fit_one_start", 1, fits, now() - t0);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    t0 = now();
    const auto b = fit::bootstrap(m, x, y, o, best, 1000, 1);
    row("bootstrap_1000", threads, 1000 - b.failed, now() - t0);
  }
  return 0;
}
