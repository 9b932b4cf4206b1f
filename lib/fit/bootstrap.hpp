#pragma once
// Bootstrap errors of a fit: the points are resampled with replacement, each replica is
// fitted again from the best fit's parameters, and the spread of the replicas' parameters
// is reported. Replicas run in parallel (OpenMP); replica r draws from cmp::Random(seed, r)
// alone, so the result is the same for any thread count.
#include "fit/fit.hpp"

#include <cstdint>
#include <vector>

namespace cmp::fit {

struct BootstrapResult {
  int replicas = 0;             // asked for
  int failed = 0;               // replicas whose fit failed (excluded from the statistics)
  std::vector<double> mean;     // per parameter (the fixed value for fixed ones)
  std::vector<double> stddev;   // sample standard deviation (n - 1)
  std::vector<double> q025;     // 2.5 % and 97.5 % quantiles (linear interpolation)
  std::vector<double> q975;
};

// Refits replicas resamples of (x, y) (and of sigma, when given: see fit()) with options (the
// starting point set to best.value). Throws cmp::ComputationError when fewer than two
// replicas succeed.
BootstrapResult bootstrap(const Model& model, const std::vector<double>& x, const std::vector<double>& y,
                          const FitOptions& options, const FitResult& best, int replicas, std::uint64_t seed,
                          const std::vector<double>& sigma = {});

}  // namespace cmp::fit
