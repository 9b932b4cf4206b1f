#include "fit/bootstrap.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::fit {

BootstrapResult bootstrap(const Model& model, const std::vector<double>& x, const std::vector<double>& y,
                          const FitOptions& options, const FitResult& best, int replicas, std::uint64_t seed,
                          const std::vector<double>& sigma) {
  const std::size_t n = x.size(), np = best.value.size();
  FitOptions o = options;
  o.start = best.value;
  std::vector<std::vector<double>> values(static_cast<std::size_t>(std::max(replicas, 0)));
#pragma omp parallel for schedule(dynamic)
  for (int r = 0; r < replicas; ++r) {
    Random rng(seed, static_cast<std::uint64_t>(r));
    std::vector<double> xs(n), ys(n), ss(sigma.empty() ? 0 : n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto j = rng.below(n);
      xs[i] = x[j], ys[i] = y[j];
      if (!sigma.empty()) ss[i] = sigma[j];
    }
    try {
      values[r] = fit(model, xs, ys, o, ss).value;
    } catch (const ComputationError&) {
      // failed replica: left empty
    }
  }
  BootstrapResult b;
  b.replicas = replicas;
  std::vector<std::vector<double>> ok;
  for (auto& v : values)
    if (v.empty()) ++b.failed;
    else ok.push_back(std::move(v));
  if (ok.size() < 2)
    throw ComputationError(fmt::format("bootstrap: only {} of {} replicas could be fitted", ok.size(), replicas));
  const double m = static_cast<double>(ok.size());
  for (std::size_t k = 0; k < np; ++k) {
    if (best.fixed[k]) {  // held: no spread (and no round-off in the mean)
      for (auto* v : {&b.mean, &b.q025, &b.q975}) v->push_back(best.value[k]);
      b.stddev.push_back(0.0);
      continue;
    }
    std::vector<double> col;
    for (const auto& v : ok) col.push_back(v[k]);
    double mean = 0;
    for (double v : col) mean += v;
    mean /= m;
    double var = 0;
    for (double v : col) var += (v - mean) * (v - mean);
    std::sort(col.begin(), col.end());
    auto quantile = [&](double q) {
      const double pos = q * (m - 1);
      const auto lo = static_cast<std::size_t>(std::floor(pos));
      const auto hi = std::min(lo + 1, col.size() - 1);
      return col[lo] + (pos - static_cast<double>(lo)) * (col[hi] - col[lo]);
    };
    b.mean.push_back(mean);
    b.stddev.push_back(std::sqrt(var / (m - 1)));
    b.q025.push_back(quantile(0.025));
    b.q975.push_back(quantile(0.975));
  }
  return b;
}

}  // namespace cmp::fit
