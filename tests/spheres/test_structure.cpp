#include "spheres/structure.hpp"
#include "spheres/structure_report.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "io/xyz.hpp"
#include "io/xyz_frame.hpp"
#include "spheres/jamming.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace cmp::spheres;

namespace {
// Face-centred cubic crystal of k^3 unit cells, nearest-neighbour distance 1, radii 1/2.
SpherePacking fcc(int k) {
  const double a = std::sqrt(2.0);
  SpherePacking p;
  p.box = Eigen::Vector3d::Constant(k * a);
  p.positions.resize(4 * k * k * k, 3);
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  int row = 0;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z)
        for (const auto& b : basis) p.positions.row(row++) << a * (x + b[0]), a * (y + b[1]), a * (z + b[2]);
  p.radii = Eigen::VectorXd::Constant(p.positions.rows(), 0.5 * (1 - 1e-12));  // touching, no overlap
  return p;
}
double g_at(const RadialDistribution& rdf, double r) { return rdf.g[static_cast<std::size_t>(r / rdf.bin_width)]; }
}  // namespace

TEST_CASE("g(r) of an ideal gas is 1") {
  SpherePacking p;
  const int n = 4000;
  p.box = Eigen::Vector3d::Constant(12.0);
  p.positions.resize(n, 3);
  cmp::Random random(3);
  for (int i = 0; i < n; ++i) p.positions.row(i) << 12 * random.uniform(), 12 * random.uniform(), 12 * random.uniform();
  p.radii = Eigen::VectorXd::Constant(n, 0.5);
  const auto rdf = radial_distribution({p}, 0.1, 5.0);
  double mean = 0;
  for (std::size_t b = 10; b < rdf.g.size(); ++b) mean += rdf.g[b] / (rdf.g.size() - 10);
  CHECK(mean == Approx(1.0).margin(0.02));
}

TEST_CASE("g(r) of an fcc crystal has its shells at 1, sqrt 2, sqrt 3, 2 with 12, 6, 24, 12 neighbours") {
  const auto p = fcc(4);
  const auto rdf = radial_distribution({p}, 0.01, 2.5);
  const int n = p.size();
  auto pairs_near = [&](double r) {
    long sum = 0;
    for (std::size_t b = 0; b < rdf.r.size(); ++b)
      if (std::abs(rdf.r[b] - r) < 0.02) sum += rdf.pair_counts[b];
    return sum;
  };
  CHECK(pairs_near(1.0) == 12L * n / 2);
  CHECK(pairs_near(std::sqrt(2.0)) == 6L * n / 2);
  CHECK(pairs_near(std::sqrt(3.0)) == 24L * n / 2);
  CHECK(pairs_near(2.0) == 12L * n / 2);
  const auto s = contact_statistics(p);
  CHECK(s.contacts == 0);  // touching within 1e-12 is not an overlap
  CHECK(s.rattlers == n);
}

TEST_CASE("g(r) of jammed packings: contact peak at r = 1, split second peak at sqrt 3 and 2") {
  std::vector<SpherePacking> packings;
  for (int seed = 1; seed <= 8; ++seed) packings.push_back(jam_spheres(50, seed, JammingParameters{}).packing);
  const auto rdf = radial_distribution(packings, 0.02, 2.3);
  // The contact peak: the largest g of all, in the bin just below r = 1 (overlaps of 1e-5).
  std::size_t peak = 0;
  for (std::size_t b = 0; b < rdf.g.size(); ++b)
    if (rdf.g[b] > rdf.g[peak]) peak = b;
  CHECK(rdf.r[peak] == Approx(0.99));
  CHECK(g_at(rdf, 0.9) == 0);
  // The split second peak: g is higher around sqrt 3 and just below 2 than in the dip between
  // them, and drops sharply past 2 (three sets of eight packings give ratios 1.05-1.08,
  // 1.25-1.32 and 1.8-1.9). Window means, since 400 spheres leave bins noisy.
  auto window = [&](double lo, double hi) {
    double sum = 0;
    int count = 0;
    for (std::size_t b = 0; b < rdf.r.size(); ++b)
      if (rdf.r[b] > lo && rdf.r[b] < hi) sum += rdf.g[b], ++count;
    return sum / count;
  };
  const double near_sqrt3 = window(1.68, 1.78), dip = window(1.80, 1.92), below_2 = window(1.94, 2.0),
               past_2 = window(2.0, 2.06);
  CHECK(near_sqrt3 > 1.02 * dip);
  CHECK(below_2 > 1.15 * dip);
  CHECK(below_2 > 1.5 * past_2);
  std::size_t second = 0;
  for (std::size_t b = 0; b < rdf.r.size(); ++b)
    if (rdf.r[b] > 1.85 && rdf.r[b] < 2.1 && (second == 0 || rdf.g[b] > rdf.g[second])) second = b;
  CHECK(rdf.r[second] == Approx(1.99));
  // Contact forces of jammed packings are broad: cv around 0.5-0.8.
  const auto s = contact_statistics(packings.front());
  CHECK(s.force_cv > 0.3);
  CHECK(s.force_cv < 1.2);
  CHECK(s.contact_number == Approx(6 - 4.0 / 50));
}

TEST_CASE("Sphere packings round-trip through extended XYZ and malformed files name their line") {
  const auto p = fcc(2);
  const auto back = frame_to_packing(packing_to_frame(p));
  CHECK(back.box == p.box);
  CHECK((back.positions - p.positions).cwiseAbs().maxCoeff() == 0);
  CHECK(back.radii == p.radii);
  const auto dir = std::filesystem::temp_directory_path() / "cmp_test_structure";
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream((dir / name).string()) << text;
    return (dir / name).string();
  };
  const std::string header = "Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"T T T\"\n";
  const auto dup = write("dup.xyz", "3\nLattice=\"4 0 0 0 4 0 0 0 4\" " + header +
                                        "X 0 0 0 0.5\nX 1 1 1 0.5\nX 1 1 1 0.5\n");
  CHECK_THROWS_WITH(read_sphere_packings(dup), Catch::Contains("dup.xyz:5") && Catch::Contains("duplicates"));
  const auto tilted = write("tilted.xyz", "1\nLattice=\"4 0 0 1 4 0 0 0 4\" " + header + "X 0 0 0 0.5\n");
  CHECK_THROWS_WITH(read_sphere_packings(tilted), Catch::Contains("orthorhombic"));
  const auto no_radius = write("noradius.xyz", "1\nLattice=\"4 0 0 0 4 0 0 0 4\" pbc=\"T T T\"\nX 0 0 0\n");
  CHECK_THROWS_WITH(read_sphere_packings(no_radius), Catch::Contains("radius"));
  const auto negative = write("negative.xyz", "2\nLattice=\"4 0 0 0 4 0 0 0 4\" " + header + "X 0 0 0 0.5\nX 2 2 2 -1\n");
  CHECK_THROWS_WITH(read_sphere_packings(negative), Catch::Contains("negative.xyz:4"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("Pooled contacts: forces relative to each packing's mean, their cv, mean Z and rattlers") {
  CHECK(coefficient_of_variation({}) == 0);
  CHECK(coefficient_of_variation({1.0, 3.0}) == Approx(0.5));
  ContactStatistics a, b;
  a.forces = {1.0, 3.0}, a.mean_force = 2.0, a.contact_number = 6.0, a.rattlers = 1;
  b.forces = {10.0, 30.0}, b.mean_force = 20.0, b.contact_number = 5.0, b.rattlers = 2;
  const auto pooled = pool_contacts({a, b});
  CHECK(pooled.relative_forces == std::vector<double>{0.5, 1.5, 0.5, 1.5});
  CHECK(pooled.force_cv == Approx(0.5));
  CHECK(pooled.mean_contact_number == Approx(5.5));
  CHECK(pooled.rattlers == 3);
}
