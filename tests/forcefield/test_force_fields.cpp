// The one finite-difference harness: every registered style of every force-field kind (shell
// terms, sphere contacts, budding-cell contacts), on the cases of cases.csv, has
//   - a gradient equal to the central difference of its energy,
//   - an add_gradient that adds (twice gives twice),
//   - its registered name, and states or gradients of the wrong size refused.
// A kind is a style table plus a fixture that builds a style on a configuration (a variant of
// cases.csv) with a state where its energy is non-zero.
#include "cells2d/contact_field.hpp"
#include "cells2d/contact_law.hpp"
#include "core/random.hpp"
#include "core/registry.hpp"
#include "forcefield/force_field.hpp"
#include "shell/styles.hpp"
#include "spheres/contact_styles.hpp"

#include "shell/shell_fixtures.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace cmp;
namespace fx = cmp::shell::fixtures;

namespace {

struct Fixture {
  std::unique_ptr<ForceField> field;
  std::vector<double> x;
};
using Make = std::function<Fixture(const std::string& style, const std::string& variant, unsigned seed)>;

struct Kind {
  std::vector<std::string> styles;  // the registered names, in table order
  Make make;
};

template <class Table>
std::vector<std::string> names_of(const Table& table) {
  std::vector<std::string> names;
  for (const auto& s : table) names.push_back(s.name);
  return names;
}

// ---- shell terms: 3 coordinates per vertex ----

const shell::MaterialParameters kMaterial{3.0, 0.3, 0.1};

// One perturbed sphere of radius 1, or two whose centres are 1.95 apart along x.
mesh::TriMesh shell_rest(const std::string& variant, unsigned seed) {
  return variant == "one-shell" ? fx::perturbed_icosphere(3, 0.02, seed) : fx::two_shells(seed);
}

// A deformed state (fx::deformed); "periodic": the two shells in a periodic box of side kPeriodicBox, their contact straddling
// the x = 0 face (found only through the minimum image); "periodic-images": the second shell
// then moved by box vectors (the same contacts, between other images).
constexpr double kPeriodicBox = 6.0;
std::vector<double> deformed(const mesh::TriMesh& rest, const std::string& variant, unsigned seed) {
  auto x = fx::deformed(rest, seed);
  if (variant == "periodic" || variant == "periodic-images")
    x = fx::moved(x, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-0.97, 1.0, 2.0));
  if (variant == "periodic-images")
    for (std::size_t v = x.size() / 6; v < x.size() / 3; ++v) {
      x[3 * v] += kPeriodicBox;
      x[3 * v + 1] -= 2 * kPeriodicBox;
      x[3 * v + 2] += 3 * kPeriodicBox;
    }
  return x;
}

const char* const kShellVariants[] = {"one-shell", "two-shells", "periodic", "periodic-images"};

template <class Table, class Parameters>
Kind shell_kind(Table table, std::function<Parameters(const mesh::TriMesh&, const std::string&, unsigned)> parameters) {
  return {names_of(table), [table, parameters](const std::string& style, const std::string& variant, unsigned seed) {
            if (std::find(std::begin(kShellVariants), std::end(kShellVariants), variant) == std::end(kShellVariants))
              throw std::invalid_argument("no shell variant " + variant);
            const auto rest = shell_rest(variant, seed);
            const auto& entry = find_style(table, style, "style");
            return Fixture{entry.make(rest, parameters(rest, variant, seed)), deformed(rest, variant, 100 + seed)};
          }};
}

// ---- soft spheres: 3 coordinates per sphere ----

// 40 polydisperse spheres in a box of about 3 x 3.4 x 3.2, dense enough that most touch several
// others and many pairs touch through a face of the box; a third of them outside the box.
Kind spheres_kind() {
  return {names_of(spheres::contact_styles()), [](const std::string& style, const std::string& variant, unsigned seed) {
            if (variant != "dense") throw std::invalid_argument("no spheres variant " + variant);
            const int n = 40;
            const Eigen::Vector3d box(3.0, 3.4, 3.2);
            Random random(seed);
            Eigen::VectorXd radii(n);
            std::vector<double> x(3 * n);
            for (int i = 0; i < n; ++i) radii[i] = 0.45 + 0.15 * random.uniform();
            for (int i = 0; i < n; ++i)
              for (int a = 0; a < 3; ++a) x[3 * i + a] = box[a] * random.uniform() - (i % 3 == 0 ? box[a] : 0);
            return Fixture{spheres::contact_style(style).make(box, radii, HertzMaterial{2.0, 0.3}), x};
          }};
}

// ---- budding cells: x, y, theta per cell ----

// 24 cells with random buds in a box of side 5, dense enough to overlap; `straddle` puts many
// within one sigma of a box edge so that contacts cross it, `sheared` adds Lees-Edwards images.
Kind cells2d_kind() {
  return {names_of(cells2d::contact_laws()), [](const std::string& style, const std::string& variant, unsigned seed) {
            if (variant != "dense" && variant != "straddle" && variant != "sheared")
              throw std::invalid_argument("no cells2d variant " + variant);
            Random rng(17, seed);
            const double L = 5;
            cells2d::Domain box;
            box.lx = box.ly = L;
            if (variant == "sheared") box.shear = 3e-4;
            std::vector<cells2d::Cell> cells(24);
            for (cells2d::Cell& c : cells) {
              c.x = rng.uniform(0, L), c.y = rng.uniform(0, L);
              if (variant != "dense") {
                c.x = rng.uniform() < 0.5 ? rng.uniform(-0.8, 0.8) : rng.uniform(0, L);
                c.y = rng.uniform() < 0.5 ? rng.uniform(L - 0.8, L + 0.8) : c.y;
              }
              c.theta = rng.uniform(-4, 4);
              c.bud = rng.uniform() < 0.15 ? 0.0 : rng.uniform(0, 1);
            }
            // An attractive range that the sticky law uses (and the others ignore).
            auto field = std::make_unique<cells2d::ContactField>(cells, box, cells2d::contact_law(style),
                                                                 cells2d::LawParameters{0.15});
            auto x = field->state();
            return Fixture{std::move(field), x};
          }};
}

// Cells in the chamber of Chapter 2: contacts and walls. `walls` presses cells against the four
// walls and into the corners; `outlet` crowds the outlet's edges and the channel, its walls and
// its open end.
Kind chamber_kind() {
  return {names_of(cells2d::contact_laws()), [](const std::string& style, const std::string& variant, unsigned seed) {
            if (variant != "walls" && variant != "outlet") throw std::invalid_argument("no chamber variant " + variant);
            Random rng(29, seed);
            cells2d::ChamberGeometry g;
            g.width = 4, g.height = 5, g.outlet = 1.6, g.channel = 1.5;
            std::vector<cells2d::Cell> cells(18);
            for (cells2d::Cell& c : cells) {
              if (variant == "walls") {
                c.x = rng.uniform() < 0.5 ? rng.uniform(-0.2, 0.6) : rng.uniform(g.width - 0.6, g.width + 0.2);
                c.y = rng.uniform() < 0.5 ? rng.uniform(-0.2, 0.6) : rng.uniform(0, g.height + 0.2);
              } else {
                c.x = rng.uniform(g.outlet_left() - 0.6, g.outlet_right() + 0.6);
                c.y = rng.uniform(-g.channel - 0.6, 0.7);
              }
              c.theta = rng.uniform(-4, 4);
              c.bud = rng.uniform() < 0.15 ? 0.0 : rng.uniform(0, 1);
            }
            auto field = std::make_unique<cells2d::ContactField>(cells, g, cells2d::contact_law(style),
                                                                 cells2d::LawParameters{0.1});
            auto x = field->state();
            return Fixture{std::move(field), x};
          }};
}

const std::map<std::string, Kind>& kinds() {
  static const std::map<std::string, Kind> all = [] {
    std::map<std::string, Kind> k;
    const auto material = [](const mesh::TriMesh&, const std::string&, unsigned) { return kMaterial; };
    k["shell-stretching"] = shell_kind<decltype(shell::stretching_styles()), shell::MaterialParameters>(
        shell::stretching_styles(), material);
    k["shell-bending"] =
        shell_kind<decltype(shell::bending_styles()), shell::MaterialParameters>(shell::bending_styles(), material);
    k["shell-pressure"] = shell_kind<decltype(shell::pressure_styles()), shell::PressureParameters>(
        shell::pressure_styles(),
        [](const mesh::TriMesh&, const std::string&, unsigned) { return shell::PressureParameters{2.5}; });
    k["shell-contact"] = shell_kind<decltype(shell::contact_styles()), shell::ContactParameters>(
        shell::contact_styles(), [](const mesh::TriMesh&, const std::string& variant, unsigned) {
          auto p = fx::contact_parameters();
          if (variant == "periodic" || variant == "periodic-images") {
            p.walls.clear();
            p.box = Eigen::Vector3d::Constant(kPeriodicBox);
          }
          return p;
        });
    k["shell-load"] = shell_kind<decltype(shell::load_styles()), shell::LoadParameters>(
        shell::load_styles(), [](const mesh::TriMesh& rest, const std::string&, unsigned seed) {
          std::mt19937_64 rng(seed);
          std::uniform_real_distribution<double> u(-1, 1);
          shell::LoadParameters p;
          for (Eigen::Index i = 0; i < 3 * rest.V.rows(); ++i) p.forces.push_back(u(rng));
          return p;
        });
    k["spheres-contact"] = spheres_kind();
    k["cells2d-contact"] = cells2d_kind();
    k["cells2d-chamber"] = chamber_kind();
    return k;
  }();
  return all;
}

struct Case {
  std::string kind, style, variant;
  unsigned seed;
  double tolerance;
};

// cases.csv: '#' lines are comments, then the header kind,style,variant,seed,tolerance.
std::vector<Case> cases() {
  const std::string path = std::string(CMP_SOURCE_DIR) + "/tests/forcefield/cases.csv";
  std::ifstream in(path);
  REQUIRE(in);
  std::vector<Case> out;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (std::exchange(header, false)) {
      REQUIRE(line == "kind,style,variant,seed,tolerance");
      continue;
    }
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
    INFO(path << ": " << line);
    REQUIRE(f.size() == 5);
    out.push_back({f[0], f[1], f[2], static_cast<unsigned>(std::stoul(f[3])), std::stod(f[4])});
  }
  REQUIRE(!out.empty());
  return out;
}

// max_i |central difference_i - g_i| / max_i |g_i|, with steps of h.
double gradient_error(const ForceField& f, std::vector<double> x, double h) {
  std::vector<double> g(x.size(), 0.0);
  f.add_gradient(x, g);
  double worst = 0, scale = 0;
  for (double v : g) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double x0 = x[i];
    x[i] = x0 + h;
    const double ep = f.energy(x);
    x[i] = x0 - h;
    const double em = f.energy(x);
    x[i] = x0;
    worst = std::max(worst, std::abs((ep - em) / (2 * h) - g[i]));
  }
  return worst / scale;
}

void check_case(const Fixture& fixture, const std::string& style, double tolerance) {
  const ForceField& f = *fixture.field;
  const auto& x = fixture.x;
  CHECK(f.name() == style);
  REQUIRE(f.state_size() == x.size());
  const double e = f.energy(x);
  CHECK(std::isfinite(e));
  CHECK(e != 0.0);
  const double error = gradient_error(f, x, 1e-6);
  INFO("gradient error " << error);
  CHECK(error < tolerance);

  // add_gradient adds: twice gives twice.
  std::vector<double> g1(x.size(), 0.0), g2(x.size(), 0.0);
  f.add_gradient(x, g1);
  f.add_gradient(x, g2);
  f.add_gradient(x, g2);
  for (std::size_t i = 0; i < x.size(); ++i) REQUIRE(g2[i] == Approx(2 * g1[i]).margin(1e-14));

  // A state or gradient of the wrong size is refused.
  std::vector<double> short_x(x.begin(), x.end() - 3), g_short(x.size() - 1, 0.0);
  CHECK_THROWS_AS(f.energy(short_x), std::invalid_argument);
  CHECK_THROWS_AS(f.add_gradient(short_x, g1), std::invalid_argument);
  CHECK_THROWS_AS(f.add_gradient(x, g_short), std::invalid_argument);
}

}  // namespace

TEST_CASE("every registered force-field style: gradient = central difference of the energy", "[forcefield]") {
  for (const Case& c : cases()) {
    const auto kind = kinds().find(c.kind);
    INFO("kind " << c.kind);
    REQUIRE(kind != kinds().end());
    const auto& registered = kind->second.styles;
    REQUIRE(!registered.empty());
    std::vector<std::string> styles = registered;
    if (c.style != "*") {
      REQUIRE(std::find(registered.begin(), registered.end(), c.style) != registered.end());
      styles = {c.style};
    }
    for (const auto& style : styles) {
      DYNAMIC_SECTION(c.kind << " " << style << " " << c.variant << " seed " << c.seed) {
        check_case(kind->second.make(style, c.variant, c.seed), style, c.tolerance);
      }
    }
  }
}

TEST_CASE("every kind of force field has cases, and every case names a kind", "[forcefield]") {
  std::map<std::string, int> rows;
  for (const Case& c : cases()) ++rows[c.kind];
  for (const auto& [name, kind] : kinds()) {
    INFO(name);
    CHECK(rows[name] > 0);
  }
  for (const auto& [name, n] : rows) {
    INFO(name);
    CHECK(kinds().count(name) == 1);
  }
}
