// What every registered shell style (lib/shell/styles.hpp) owes beyond its gradient (which the
// force-field harness, tests/forcefield, checks for every style of every kind), on random
// perturbed icosahedral meshes; adding a style to a table adds it here with no new test code:
//   - energy invariant under rigid translations and rotations (contacts: those that keep the
//     walls, on two overlapping shells)
//   - stretching and bending: zero energy and zero gradient on the rest mesh
#include "shell/hertz_contacts.hpp"
#include "shell/shell_contact_term.hpp"
#include "shell/styles.hpp"
#include "shell/vertex_face_contacts.hpp"

#include "core/errors.hpp"

#include "shell_fixtures.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;

namespace {

const MaterialParameters kStyleMaterial{3.0, 0.3, 0.1};
const PressureParameters kStylePressure{2.5};

cmp::mesh::TriMesh one_shell(unsigned seed) { return fx::perturbed_icosphere(3, 0.02, seed); }

using fx::contact_parameters;
using fx::deformed;
using fx::two_shells;

template <class Table, class Parameters>
void check_table(Table table, const Parameters& params, bool zero_at_rest,
                 cmp::mesh::TriMesh (*make_rest)(unsigned) = &one_shell, bool keeps_walls = false) {
  REQUIRE(!table.empty());
  for (const auto& style : table) {
    for (unsigned seed : {1u, 2u, 3u}) {
      INFO("style " << style.name << " seed " << seed);
      const auto rest = make_rest(seed);
      const auto term = style.make(rest, params);
      CHECK(term->name() == style.name);
      CHECK(term->vertex_count() == rest.V.rows());
      const auto x = deformed(rest, 100 + seed);
      const double e = term->energy(x);
      CHECK(std::isfinite(e));
      CHECK(e != 0.0);
      std::vector<double> g1(x.size(), 0.0);
      term->add_gradient(x, g1);

      // Contacts with walls at fixed z are invariant under the motions that keep the walls:
      // rotations about z and translations in the xy plane.
      const Eigen::Vector3d axis = keeps_walls ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(1.0, -2.0, 0.5 * seed).normalized();
      const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7 + seed, axis).toRotationMatrix();
      const Eigen::Vector3d t(0.3, -1.2, keeps_walls ? 0.0 : 2.0);
      CHECK(term->energy(fx::moved(x, Eigen::Matrix3d::Identity(), t)) == Approx(e).epsilon(1e-11));
      CHECK(term->energy(fx::moved(x, R, Eigen::Vector3d::Zero())) == Approx(e).epsilon(1e-11));
      CHECK(term->energy(fx::moved(x, R, t)) == Approx(e).epsilon(1e-11));

      if (zero_at_rest) {
        const auto x0 = fx::state(rest.V);
        CHECK(std::abs(term->energy(x0)) < 1e-13 * std::abs(e));
        std::vector<double> g0(x0.size(), 0.0);
        term->add_gradient(x0, g0);
        double gmax = 0, g1max = 0;
        for (double v : g0) gmax = std::max(gmax, std::abs(v));
        for (double v : g1) g1max = std::max(g1max, std::abs(v));
        CHECK(gmax < 1e-11 * g1max);
      }
    }
  }
}

}  // namespace

TEST_CASE("every stretching style is invariant under rigid motions", "[shell][styles]") {
  check_table(stretching_styles(), kStyleMaterial, true);
}

TEST_CASE("every bending style is invariant under rigid motions", "[shell][styles]") {
  check_table(bending_styles(), kStyleMaterial, true);
}

TEST_CASE("every pressure style is invariant under rigid motions", "[shell][styles]") {
  check_table(pressure_styles(), kStylePressure, false);
}

TEST_CASE("every contact style is invariant under rigid motions", "[shell][styles]") {
  check_table(contact_styles(), contact_parameters(), false, &two_shells, true);
}

TEST_CASE("style tables have unique names and one-line descriptions and find by name", "[shell][styles]") {
  std::vector<std::string> names;
  for (const auto& s : stretching_styles()) {
    names.push_back(s.name);
    CHECK(&stretching_style(s.name) == &s);
  }
  for (const auto& s : bending_styles()) {
    names.push_back(s.name);
    CHECK(&bending_style(s.name) == &s);
  }
  for (const auto& s : pressure_styles()) {
    names.push_back(s.name);
    CHECK(&pressure_style(s.name) == &s);
  }
  for (const auto& s : contact_styles()) {
    names.push_back(s.name);
    CHECK(&contact_style(s.name) == &s);
  }
  auto sorted = names;
  std::sort(sorted.begin(), sorted.end());
  CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  for (const auto& s : stretching_styles()) CHECK(std::string(s.description).find('\n') == std::string::npos);
  CHECK_THROWS_WITH(stretching_style("fem"), Catch::Contains("unknown stretching model 'fem'") &&
                                                 Catch::Contains("svk") && Catch::Contains("springs-kot"));
  CHECK_THROWS_WITH(bending_style("none"), Catch::Contains("unknown bending model 'none' (known: hinge, hinge-uniform)"));
  CHECK_THROWS_WITH(pressure_style(""), Catch::Contains("unknown pressure model ''"));
}

// set_box of the shell-shell contact styles (the same interface on each).
static void set_box_of(EnergyTerm& term, const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) {
  auto* c = dynamic_cast<ShellContactTerm*>(&term);
  REQUIRE(c);
  c->set_box(lengths, periodic);
}

TEST_CASE("every shell-contact style: its touches carry exactly its forces, between different shells",
          "[shell][styles]") {
  // What a compression's virial and Z and analyze's contact forces read (touches()) must be
  // the force the relaxation felt (add_gradient): rebuilt from the touches, vertex by vertex.
  ContactParameters p = contact_parameters();
  p.walls.clear();
  int styles = 0;
  for (const auto& style : contact_styles())
    for (bool boxed : {false, true})
      for (unsigned seed : {1u, 2u}) {
        const auto rest = two_shells(seed);
        ContactParameters q = p;
        if (boxed) q.box = Eigen::Vector3d(6, 6, 6);
        const auto term = style.make(rest, q);
        const auto* law = dynamic_cast<const ShellContactTerm*>(term.get());
        if (!law) continue;  // walls
        INFO(style.name << (boxed ? " in a periodic box" : " in open space") << " seed " << seed);
        ++styles;
        auto x = deformed(rest, 300 + seed);
        if (boxed) x = fx::moved(x, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-0.97, 1.0, 2.0));
        std::vector<double> g(x.size(), 0.0), rebuilt(x.size(), 0.0);
        term->add_gradient(x, g);
        const auto touches = law->touches(x);
        REQUIRE(touches.size() > 10);
        const auto& shell = law->vertex_shells();
        for (const auto& t : touches) {
          CHECK(t.overlap > 0);
          CHECK(t.r == Approx(t.d.norm()).epsilon(1e-14));
          CHECK(t.weights.sum() == Approx(1.0).epsilon(1e-14));
          for (int k = 0; k < 3; ++k)
            if (t.corners[k] >= 0) CHECK(shell[t.corners[k]] != shell[t.i]);
          // On i: force along d; on the corners: minus that, split by the weights.
          for (int a = 0; a < 3; ++a) {
            const double f = t.force * t.d[a] / t.r;
            rebuilt[3 * t.i + a] -= f;
            for (int k = 0; k < 3; ++k)
              if (t.corners[k] >= 0) rebuilt[3 * t.corners[k] + a] += t.weights[k] * f;
          }
        }
        double largest = 0, error = 0;
        for (std::size_t k = 0; k < g.size(); ++k) {
          largest = std::max(largest, std::abs(g[k]));
          error = std::max(error, std::abs(g[k] - rebuilt[k]));
        }
        REQUIRE(largest > 0);
        CHECK(error < 1e-12 * largest);
      }
  CHECK(styles == 8);  // hertz-vertices and hertz-faces, open and periodic, two seeds
}

TEST_CASE("hertz-faces: the Verlet list kept over small moves finds what a fresh search finds", "[shell][faces]") {
  // A walk of small random moves (each below the list's tolerance, together far beyond it, the
  // contact sliding over new triangles): the term that keeps and rebuilds its list gives the energy and forces of a term built anew
  // at every point.
  ContactParameters p = contact_parameters();
  p.walls.clear();
  const auto rest = two_shells(3);
  const auto kept = contact_style("hertz-faces").make(rest, p);
  auto x = deformed(rest, 400);
  std::mt19937 rng(5);
  std::normal_distribution<double> step(0.0, 0.002);
  const std::size_t second = x.size() / 2;  // the second shell slides along y past the first
  for (int move = 0; move < 150; ++move) {
    for (double& v : x) v += step(rng);
    for (std::size_t k = second + 1; k < x.size(); k += 3) x[k] += 0.01;
    const auto fresh = contact_style("hertz-faces").make(rest, p);
    INFO("move " << move);
    const double e = fresh->energy(x);
    CHECK(kept->energy(x) == Approx(e).epsilon(1e-14).margin(1e-300));
    std::vector<double> g1(x.size(), 0.0), g2(x.size(), 0.0);
    kept->add_gradient(x, g1);
    fresh->add_gradient(x, g2);
    double error = 0, largest = 0;
    for (std::size_t k = 0; k < g1.size(); ++k) {
      error = std::max(error, std::abs(g1[k] - g2[k]));
      largest = std::max(largest, std::abs(g2[k]));
    }
    CHECK(error <= 1e-13 * largest);
  }
}

TEST_CASE("hertz-vertices and hertz-faces in a periodic box: a shell may sit in any image (forces: tests/forcefield)",
          "[shell][styles]") {
  // Two overlapping shells (as above) in a periodic box of side 6 along every axis, placed so
  // that the contact region straddles the x = 0 face: the pairs are found only through the
  // minimum image.
  ContactParameters p = contact_parameters();
  p.walls.clear();
  const double L = 6.0;
  p.box = Eigen::Vector3d(L, L, L);
  for (const char* style : {"hertz-vertices", "hertz-faces"})
  for (unsigned seed : {1u, 2u}) {
    INFO(style << " seed " << seed);
    const auto rest = two_shells(seed);
    const auto periodic = contact_style(style).make(rest, p);
    ContactParameters open = p;
    open.box.reset();
    const auto free = contact_style(style).make(rest, open);
    auto x = deformed(rest, 200 + seed);
    // Centre the pair on the x = 0 face: the first shell's vertices at x < 0 wrap to x ~ L.
    x = fx::moved(x, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-0.97, 1.0, 2.0));
    const double e = free->energy(x);
    REQUIRE(e > 0);
    CHECK(periodic->energy(x) == Approx(e).epsilon(1e-13));
    // Shift the second shell by box vectors: the open-space energy drops to zero, the periodic
    // one stays (the same pairs, the same distances up to round-off of the shift).
    const long half = rest.V.rows() / 2;
    auto y = x;
    for (long v = half; v < rest.V.rows(); ++v) {
      y[3 * v] += L;
      y[3 * v + 1] -= 2 * L;
      y[3 * v + 2] += 3 * L;
    }
    CHECK(free->energy(y) == 0.0);
    CHECK(periodic->energy(y) == Approx(e).epsilon(1e-11));
    // A periodic side under 4 R_v (4 delta) is refused.
    CHECK_THROWS_AS(set_box_of(*periodic, Eigen::Vector3d(L, 0.5, L), {true, true, true}), cmp::UsageError);
    set_box_of(*periodic, Eigen::Vector3d(L, 0.5, L), {true, false, true});
    CHECK(periodic->energy(x) == Approx(e).epsilon(1e-13));
  }
}
