// The constant-volume update (lib/shell/volume_rule.hpp) on a synthetic packing whose volumes
// answer the turgors linearly in logs: ln V_s = ln V0_s + sum_t C_st (ln Pi_t - ln Pi*_t), C
// with one eigenvalue `common` on the mode where all Pi move together and `difference` on every
// mode where they move against each other. Near confluence the first is small (the box holds the
// packing) and the second can exceed 2 (volume moves easily between flattened neighbours).
#include "shell/volume_rule.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace cmp::shell;

namespace {

struct Packing {
  double common, difference;
  std::vector<double> target{1.0, 1.1, 0.9, 1.05};  // V0_s
  std::vector<double> fixed_point{1.0, 1.3, 0.8, 1.1};  // Pi*_s

  std::vector<double> volumes(const std::vector<double>& pi) const {
    const std::size_t n = pi.size();
    double mean = 0;
    for (std::size_t s = 0; s < n; ++s) mean += std::log(pi[s] / fixed_point[s]) / static_cast<double>(n);
    std::vector<double> v(n);
    for (std::size_t s = 0; s < n; ++s)
      v[s] = target[s] * std::exp(common * mean + difference * (std::log(pi[s] / fixed_point[s]) - mean));
    return v;
  }
  double worst_error(const std::vector<double>& pi) const {
    const auto v = volumes(pi);
    double worst = 0;
    for (std::size_t s = 0; s < v.size(); ++s) {
      const double e = std::abs(v[s] - target[s]) / target[s];
      if (!(e <= worst)) worst = std::isfinite(e) ? e : HUGE_VAL;  // a diverged volume never counts as in the band
    }
    return worst;
  }
};

// Updates until every volume is within 1e-3 of its target (or `cap`); the count.
int updates_to_band(const Packing& p, VolumeRuleKind kind, std::vector<double> pi, int cap = 2000) {
  VolumeRule rule(kind);
  for (int k = 0; k < cap; ++k) {
    if (p.worst_error(pi) <= 1e-3) return k;
    pi = rule.next(pi, p.volumes(pi), p.target);
  }
  return cap;
}

}  // namespace

TEST_CASE("volume rule: the thesis's rule is Pi (1 + (V0 - V)/V)", "[shell][volume]") {
  VolumeRule rule(VolumeRuleKind::Thesis);
  const auto pi = rule.next({2.0, 3.0}, {1.0, 2.0}, {1.1, 1.9});
  CHECK(pi[0] == 2.0 * (1.0 + (1.1 - 1.0) / 1.0));
  CHECK(pi[1] == 3.0 * (1.0 + (1.9 - 2.0) / 2.0));
}

TEST_CASE("volume rule: a squeezed packing (the common mode barely answers) reaches the band in a few updates",
          "[shell][volume]") {
  // Every Pi 30 % short of its fixed point: all volumes about 1 % short.
  const Packing p{0.03, 0.5};
  const std::vector<double> start{0.7 * 1.02, 0.7 * 1.3 * 1.05, 0.7 * 0.8 * 1.01, 0.7 * 1.1 * 0.97};
  const int thesis = updates_to_band(p, VolumeRuleKind::Thesis, start);
  const int accelerated = updates_to_band(p, VolumeRuleKind::Accelerated, start);
  INFO("thesis " << thesis << ", accelerated " << accelerated);
  CHECK(thesis > 60);
  CHECK(accelerated < 15);
}

TEST_CASE("volume rule: volume moving easily between neighbours (c > 2) makes the thesis's rule swing, the "
          "accelerated rule damps it",
          "[shell][volume]") {
  const Packing p{0.03, 2.6};
  const std::vector<double> start{1.001, 1.3 * 1.002, 0.8 * 0.999, 1.1 * 0.998};
  const int thesis = updates_to_band(p, VolumeRuleKind::Thesis, start);
  const int accelerated = updates_to_band(p, VolumeRuleKind::Accelerated, start);
  INFO("thesis " << thesis << ", accelerated " << accelerated);
  CHECK(thesis == 2000);  // never: each update overshoots by more
  CHECK(accelerated < 30);
}

TEST_CASE("volume rule: shells that answer alike in both modes reach the band no later than with the thesis's rule",
          "[shell][volume]") {
  for (double c : {1.0, 0.3, 0.05}) {
    const Packing p{c, c};
    const std::vector<double> start{1.1, 1.3 * 0.95, 0.8 * 1.02, 1.1};
    const int thesis = updates_to_band(p, VolumeRuleKind::Thesis, start);
    const int accelerated = updates_to_band(p, VolumeRuleKind::Accelerated, start);
    INFO("c = " << c << ": thesis " << thesis << ", accelerated " << accelerated);
    CHECK(accelerated <= thesis);
    if (c >= 0.3) CHECK(accelerated < 20);
  }
}

TEST_CASE("volume rule: one update moves Pi by at most a fifth", "[shell][volume]") {
  VolumeRule rule;
  const auto pi = rule.next({1.0, 1.0}, {0.5, 0.6}, {1.0, 1.0});
  CHECK(pi[0] == Approx(1.2));
  CHECK(pi[1] == Approx(1.2));
}

TEST_CASE("volume rule: names", "[shell][volume]") {
  CHECK(parse_volume_rule("thesis") == VolumeRuleKind::Thesis);
  CHECK(parse_volume_rule(volume_rule_name(VolumeRuleKind::Accelerated)) == VolumeRuleKind::Accelerated);
  CHECK(parse_volume_rule(volume_rule_name(VolumeRuleKind::Projected)) == VolumeRuleKind::Projected);
  CHECK_THROWS_AS(parse_volume_rule("secant"), cmp::UsageError);
}
