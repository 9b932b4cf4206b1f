// shellpack analyze's composition (lib/packrun/packing_analysis, analyze_batch): lattice
// packings of icosphere shells in periodic cubes, whose contact numbers, Voronoi facets and
// g(r) peaks are known exactly, and the `# key=value` lines of a packing OFF.
#include "shell/packing_fixtures.hpp"

#include "core/errors.hpp"
#include "packrun/analyze_batch.hpp"
#include "packrun/packing_analysis.hpp"
#include "packing/shell_packing_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using namespace cmp;
using namespace cmp::packrun;
using namespace cmp::packing;

namespace {

// n^3 cubic cells of side a, one icosphere (level 2, radius r) per simple cubic or FCC site.
ShellPackingFile lattice_packing(int n, double a, bool fcc, double r) {
  const auto mesh = shell::fixtures::icosphere_vertex_on_x(2, r);
  shell::fixtures::SyntheticPacking s;
  for (const auto& site : shell::fixtures::cubic_lattice(n, a, fcc)) shell::fixtures::add_shell(s, mesh, site);
  ShellPackingFile p;
  p.file = fcc ? "fcc.off" : "sc.off";
  p.V = s.V;
  p.F = s.F;
  p.offsets = s.offsets;
  p.box = Eigen::Vector3d::Constant(n * a);
  p.periodic = {true, true, true};
  p.d0 = 1;
  p.d0_source = "file";
  return p;
}

// The r of the largest g among the bins within [lo, hi].
double peak(const spheres::RadialDistribution& g, double lo, double hi) {
  double best = -1, at = 0;
  for (std::size_t b = 0; b < g.r.size(); ++b)
    if (g.r[b] >= lo && g.r[b] <= hi && g.g[b] > best) best = g.g[b], at = g.r[b];
  return at;
}

}  // namespace

TEST_CASE("analyze: simple cubic lattice of touching shells, Z = 6, 6 Voronoi facets, g(r) peaks at 1, sqrt 2, sqrt 3",
          "[analyze]") {
  // Radius 0.55 at spacing 1: nearest neighbours overlap, next ones (sqrt 2) are 0.3 apart.
  auto p = lattice_packing(3, 1.0, false, 0.55);
  p.keys.vertex_radius = 0.04;
  p.keys.youngs_modulus = 1.0;
  p.keys.turgor = std::vector<double>(27, 0.5);
  p.keys.turgor[0] = 0.8;
  p.keys.p0 = 0.25;
  AnalyzeOptions o;
  o.bin_width = 0.02;
  const auto a = analyze_packing(p, o);
  CHECK(a.particles == 27);
  CHECK(a.phi_source == "shell_volumes");
  CHECK(a.contacts_per_shell == std::vector<int>(27, 6));
  CHECK(a.voronoi_faces == std::vector<int>(27, 6));
  const auto s = summarise(a);
  CHECK(*s.contacts == 81);
  CHECK(*s.Z == 6.0);
  CHECK(*s.dZ == Approx(4.0 / 27.0));
  CHECK(*s.voronoi_faces_mean == 6.0);
  CHECK(*s.turgor_mean == Approx((0.8 + 26 * 0.5) / 27));
  CHECK(*s.turgor_mean_p0 == Approx((0.8 + 26 * 0.5) / 27 / 0.25));
  CHECK(*s.turgor_cv > 0);
  CHECK(*s.force_normal_mean > 0);
  CHECK(*s.mu_eff >= 0);
  CHECK_FALSE(s.wall_pressure);
  REQUIRE(a.rdf);
  CHECK(peak(*a.rdf, 0.9, 1.1) == Approx(1.0).margin(0.011));
  CHECK(peak(*a.rdf, 1.3, 1.5) == Approx(std::sqrt(2.0)).margin(0.011));
  CHECK(peak(*a.rdf, 1.6, 1.8) == Approx(std::sqrt(3.0)).margin(0.011));
  // Newton's third law contact by contact, through the periodic faces too.
  for (const auto& c : a.contacts)
    for (const auto& d : a.contacts)
      if (d.m == c.n && d.n == c.m && d.image == -c.image) CHECK((c.force + d.force).norm() <= 1e-12 * c.force.norm());
}

TEST_CASE("analyze: in a 2 x 2 x 2 simple cubic box each shell touches two images of each neighbour: still Z = 6",
          "[analyze]") {
  auto p = lattice_packing(2, 1.0, false, 0.55);
  p.keys.vertex_radius = 0.04;
  p.keys.youngs_modulus = 1.0;
  const auto a = analyze_packing(p, AnalyzeOptions{});
  CHECK(a.contacts_per_shell == std::vector<int>(8, 6));
  CHECK(a.voronoi_faces == std::vector<int>(8, 6));
  // Each image is its own contact, pushing along its own axis: none cancels.
  for (const auto& c : a.contacts) CHECK(c.force.norm() > 0);
}

TEST_CASE("analyze: FCC lattice, Z = 12, 12 Voronoi facets, g(r) peaks at 1, sqrt 2, sqrt 3, 2", "[analyze]") {
  auto p = lattice_packing(2, std::sqrt(2.0), true, 0.55);  // nearest neighbours at distance 1
  p.keys.thickness = 0.1;                                   // R_v = t without vertex_radius=
  AnalyzeOptions o;
  o.bin_width = 0.02;
  const auto a = analyze_packing(p, o);
  CHECK(a.contacts_per_shell == std::vector<int>(32, 12));
  CHECK(a.voronoi_faces == std::vector<int>(32, 12));
  CHECK_FALSE(a.has_forces);  // no E
  CHECK(a.warnings.size() == 2);  // no turgor, no E
  REQUIRE(a.rdf);
  CHECK(peak(*a.rdf, 0.9, 1.1) == Approx(1.0).margin(0.011));
  CHECK(peak(*a.rdf, 1.3, 1.5) == Approx(std::sqrt(2.0)).margin(0.011));
  CHECK(peak(*a.rdf, 1.6, 1.8) == Approx(std::sqrt(3.0)).margin(0.011));
  CHECK(peak(*a.rdf, 1.9, 2.1) == Approx(2.0).margin(0.011));
  // Asked for the contact table without E: refused, naming the file.
  o.require_contacts = true;
  CHECK_THROWS_AS(analyze_packing(p, o), InputError);
}

TEST_CASE("analyze: a non-cubic periodic box has no Voronoi column, a walled one no g(r)", "[analyze]") {
  auto p = lattice_packing(2, 1.0, false, 0.4);
  p.box = Eigen::Vector3d(2, 2, 2.5);
  p.keys.phi = 0.5;
  auto a = analyze_packing(p, AnalyzeOptions{});
  CHECK(a.voronoi_faces.empty());
  CHECK(a.phi == 0.5);
  CHECK(a.phi_source == "file");
  CHECK_FALSE(a.has_contacts);
  p.periodic = {true, true, false};
  a = analyze_packing(p, AnalyzeOptions{});
  CHECK_FALSE(a.rdf);
  AnalyzeOptions o;
  o.require_rdf = true;
  CHECK_THROWS_AS(analyze_packing(p, o), InputError);
  // A duplicated shell.
  p = lattice_packing(2, 1.0, false, 0.4);
  p.V.middleRows(p.offsets[1], p.offsets[2] - p.offsets[1]) = p.V.middleRows(0, p.offsets[1]);
  CHECK_THROWS_AS(analyze_packing(p, AnalyzeOptions{}), InputError);
}

TEST_CASE("analyze: the key lines of a packing OFF, strictly", "[analyze]") {
  const std::vector<std::string> good{"tool=shellpack compress x", "phi=0.85", "E=2", "nu=0.45", "thickness=0.02",
                                      "vertex_radius=0.03", "P0=0.005", "bending=none", "turgor=1 2 3",
                                      "volume0=0.5 0.5 0.5", "free text without a key"};
  std::vector<long> lines(good.size());
  for (std::size_t i = 0; i < lines.size(); ++i) lines[i] = static_cast<long>(i + 2);
  const auto k = parse_packing_keys(good, lines, "p.off", 3);
  CHECK(*k.phi == 0.85);
  CHECK(*k.youngs_modulus == 2);
  CHECK(*k.poisson_ratio == 0.45);
  CHECK(*k.thickness == 0.02);
  CHECK(*k.vertex_radius == 0.03);
  CHECK(*k.p0 == 0.005);
  CHECK(*k.bending == "none");
  CHECK(k.turgor == std::vector<double>{1, 2, 3});
  CHECK(k.volume0 == std::vector<double>{0.5, 0.5, 0.5});
  for (const std::string bad : {"phi=abc", "E=-1", "nu=0.7", "turgor=1 2", "volume0=1 2 0", "phi=0.8 0.9", "E=", "bending="}) {
    std::vector<std::string> c = good;
    c[4] = bad;
    try {
      parse_packing_keys(c, lines, "p.off", 3);
      FAIL("accepted " << bad);
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("p.off:6:") != std::string::npos);
    }
  }
}

TEST_CASE("analyze: the summary table has one row per packing with the documented columns", "[analyze]") {
  auto p = lattice_packing(2, 1.0, false, 0.4);
  const auto a = analyze_packing(p, AnalyzeOptions{});
  std::ostringstream out;
  write_analysis_summary(out, {a, a}, "test");
  const std::string s = out.str();
  CHECK(s.find("file,particles,phi,phi_source,d0,d0_source,bending,contacts,Z,dZ,turgor_mean_P,turgor_mean_P0,turgor_cv,"
               "asphericity_mean_d02,delta_eps_mean,force_normal_mean_F,force_normal_cv,force_tangential_mean_F,mu_eff,"
               "wall_pressure_P,coverage,wall_pressure_over_coverage_P,voronoi_faces_mean\n") != std::string::npos);
  CHECK(s.find("sc.off,8,") != std::string::npos);
  long rows = 0;
  for (std::size_t i = s.find("sc.off,"); i != std::string::npos; i = s.find("sc.off,", i + 1)) ++rows;
  CHECK(rows == 2);
}
