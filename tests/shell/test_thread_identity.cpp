// Same input, same bits on 1, 2 and 3 threads: every force term of a 2562-vertex shell (with
// the terms' parallel passes switched on from 2048 elements, element_assembly.hpp), their energies, the total
// force, and a short FIRE relaxation (whose vector passes are parallel too from 2048 vertices).
#include "shell/element_assembly.hpp"
#include "shell/relax.hpp"
#include "shell/styles.hpp"

#include "shell_fixtures.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <random>
#include <vector>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;

namespace {

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// Every stretching and bending style and turgor on a jittered level-5 icosphere.
ShellSystem all_terms() {
  const auto rest = fx::perturbed_icosphere(5, 0.002, 7, 2.5);
  ShellSystem s(rest);
  const MaterialParameters material{25.0, 0.3, 0.1};
  for (const auto& style : stretching_styles()) s.add(style.make(rest, material));
  for (const auto& style : bending_styles()) s.add(style.make(rest, material));
  s.add(pressure_style("turgor").make(rest, {0.25}));
  return s;
}

struct Run {
  std::vector<double> energies;
  Eigen::VectorXd forces, relaxed;
  long iterations = 0;
};

Run run_on(int threads) {
  const int saved = omp_get_max_threads();
  const long saved_threshold = ElementAssembly::parallel_elements();
  ElementAssembly::set_parallel_elements(2048);  // the passes run on all threads at this size
  omp_set_num_threads(threads);
  ShellSystem s = all_terms();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  Eigen::VectorXd y = 1.05 * s.x;
  for (Eigen::Index i = 0; i < y.size(); ++i) y[i] += u(rng);
  Run r;
  r.energies = s.term_energies(y);
  r.energies.push_back(s.energy(y));
  s.forces(y, r.forces);
  RelaxParameters p;
  p.force_scale = default_force_scale(s.rest(), 25.0, 0.1);
  p.fire.max_iterations = 40;
  s.x = y;
  r.iterations = relax(s, p).iterations;
  r.relaxed = s.x;
  omp_set_num_threads(saved);
  ElementAssembly::set_parallel_elements(saved_threshold);
  return r;
}

}  // namespace

TEST_CASE("forces, energies and a FIRE relaxation of a shell are byte-identical on 1, 2 and 3 threads",
          "[shell][threads]") {
  const Run one = run_on(1);
  REQUIRE(one.energies.size() == 8);  // four stretching, two bending styles, turgor, total
  REQUIRE(one.iterations == 40);
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    const Run many = run_on(threads);
    REQUIRE(many.energies.size() == one.energies.size());
    CHECK(std::memcmp(many.energies.data(), one.energies.data(), sizeof(double) * one.energies.size()) == 0);
    CHECK(same_bits(many.forces, one.forces));
    CHECK(many.iterations == one.iterations);
    CHECK(same_bits(many.relaxed, one.relaxed));
    CHECK(!same_bits(many.relaxed, 1.05 * one.relaxed));  // a relaxation moved the state (not a vacuous check)
  }
}
