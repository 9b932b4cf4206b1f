// The model registry: analytic gradients against finite differences, domains, lookup.
#include "core/errors.hpp"
#include "fit/models.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace cmp;

namespace {
// A parameter vector inside every model's domain for x in [0.2, 0.4].
std::vector<double> typical(const fit::Model& m) {
  if (m.name == "threshold") return {0.035, 3.67, 1.1};
  if (m.name == "sigmoid") return {0.3, 0.02};
  if (m.name == "tortuosity") return {0.74, 0.124, -0.38};
  std::vector<double> p{50.0, 0.146, 0.83};
  p.resize(m.params.size());
  return p;
}
}  // namespace

TEST_CASE("every analytic gradient matches central differences", "[fit]") {
  for (const auto& m : fit::models()) {
    auto p = typical(m);
    for (double x : {0.2, 0.3, 0.4}) {
      std::vector<double> g(p.size());
      m.gradient(x, p.data(), g.data());
      for (std::size_t k = 0; k < p.size(); ++k) {
        const double h = 1e-6 * std::max(1.0, std::abs(p[k]));
        auto up = p, down = p;
        up[k] += h, down[k] -= h;
        const double fd = (m.value(x, up.data()) - m.value(x, down.data())) / (2 * h);
        INFO(m.name << " d/d" << m.params[k].name << " at x = " << x);
        CHECK(g[k] == Approx(fd).epsilon(1e-6).margin(1e-9));
      }
    }
  }
}

TEST_CASE("the registry holds the laws of Table S5.1 with the printed exponents", "[fit]") {
  std::set<std::string> names;
  for (const auto& m : fit::models()) names.insert(m.name);
  CHECK(names == std::set<std::string>{"kc-classical", "kc-percolation", "kc-fixed", "power", "hydraulic-radius",
                                       "tortuosity", "threshold", "sigmoid"});
  // Eq. 5.8 with gamma = 1.76 is the fixed-exponent form 2.52.
  const auto& perc = fit::find_model("kc-percolation");
  const auto& fixed = fit::find_model("kc-fixed");
  const double p3[] = {2.0, 0.141, 1.76}, p2[] = {2.0, 0.141};
  CHECK(perc.value(0.3, p3) == Approx(fixed.value(0.3, p2)).epsilon(1e-14));
  CHECK(fixed.value(0.3, p2) == Approx(2.0 * std::pow(0.159, 2.52) * 0.09 / 0.49).epsilon(1e-14));
  // Classical KC: C phi^3 / (1 - phi)^2; hydraulic radius C phi / (1 - phi).
  const double c[] = {3.0};
  CHECK(fit::find_model("kc-classical").value(0.5, c) == Approx(1.5));
  CHECK(fit::find_model("hydraulic-radius").value(0.5, c) == Approx(3.0));
  // Tortuosity exponent fixed at -0.38 by default.
  const auto& tau = fit::find_model("tortuosity");
  CHECK(tau.params[2].fixed_by_default);
  CHECK(tau.params[2].start == -0.38);
  // Threshold: phi_c(0.04) = 0.141 with the N = 50 values (Table S5.1's A = 3.67, not the 3.76 of 5.5.6, which gives 0.144).
  const double t[] = {0.035, 3.67, 1.1};
  CHECK(fit::find_model("threshold").value(0.04, t) == Approx(0.1414).margin(1e-4));
  // Sigmoid is 1/2 at phi_c.
  const double s[] = {0.141, 0.01};
  CHECK(fit::find_model("sigmoid").value(0.141, s) == 0.5);
}

TEST_CASE("an unknown model name is a usage error listing the models", "[fit]") {
  try {
    fit::find_model("kozeny");
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK(std::string(e.what()).find("kc-percolation") != std::string::npos);
  }
}
