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

TEST_CASE("a mesh of separate shells (assembled block by block) gives each shell the forces it has alone, to the bit",
          "[shell][threads]") {
  // Six jittered 642-vertex shells side by side: 7680 triangles, blocks of whole shells.
  const int shells = 6;
  std::vector<cmp::mesh::TriMesh> pieces;
  for (int k = 0; k < shells; ++k) {
    auto m = fx::perturbed_icosphere(4, 0.01, 20 + k, 1.0);
    m.V.col(0).array() += 3.0 * k;
    pieces.push_back(m);
  }
  cmp::mesh::TriMesh all;
  all.V.resize(shells * pieces[0].V.rows(), 3);
  all.F.resize(shells * pieces[0].F.rows(), 3);
  for (int k = 0; k < shells; ++k) {
    all.V.middleRows(k * pieces[0].V.rows(), pieces[0].V.rows()) = pieces[k].V;
    all.F.middleRows(k * pieces[0].F.rows(), pieces[0].F.rows()) =
        pieces[k].F.array() + static_cast<int>(k * pieces[0].V.rows());
  }
  const MaterialParameters material{25.0, 0.3, 0.1};
  // The styles whose elements are local (edge springs with Kot's constants use the whole
  // mesh's area, so a shell alone gets other constants).
  const auto add_terms = [&](ShellSystem& s, const cmp::mesh::TriMesh& rest) {
    s.add(stretching_style("svk").make(rest, material));
    for (const auto& style : bending_styles()) s.add(style.make(rest, material));
    s.add(pressure_style("turgor").make(rest, {0.25}));
  };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  Eigen::VectorXd y(3 * all.V.rows());
  for (Eigen::Index i = 0; i < y.size(); ++i) y[i] = all.V.data()[i] * 1.04 + u(rng);
  const int saved = omp_get_max_threads();
  const long saved_threshold = ElementAssembly::parallel_elements();
  ElementAssembly::set_parallel_elements(2048);
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    omp_set_num_threads(threads);
    ShellSystem s(all);
    add_terms(s, all);
    Eigen::VectorXd f;
    s.forces(y, f);
    const Eigen::Index n = 3 * pieces[0].V.rows();
    for (int k = 0; k < shells; ++k) {
      ShellSystem one(pieces[k]);
      add_terms(one, pieces[k]);
      Eigen::VectorXd fk;
      one.forces(y.segment(k * n, n), fk);
      CHECK(same_bits(fk, f.segment(k * n, n)));
    }
  }
  omp_set_num_threads(saved);
  ElementAssembly::set_parallel_elements(saved_threshold);
}
