// Monte Carlo annealing of A.2.2: the fast energy is the brute-force energy, the schedule is
// the thesis's, the meshes reach Table A.5's quality, and lower T_end gives better meshes
// (Table A.6).
#include "mesh/manifold.hpp"
#include "mesh/quality.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp;
using spheremesh::AnnealingParameters;

namespace {
AnnealingParameters thesis_defaults(int n, std::uint64_t seed) {
  AnnealingParameters p;
  p.points = n;
  p.radius = 2.5;  // Table A.5's node counts need R = 2.5 (and floor), not the R = 2 of its caption
  p.seed = seed;
  return p;
}

mesh::MeshQuality annealed_quality(const AnnealingParameters& p) {
  const auto result = spheremesh::anneal_on_sphere(p);
  const auto faces = spheremesh::spherical_delaunay(result.points);
  return mesh::mesh_quality(result.points, faces);
}
}  // namespace

TEST_CASE("Temperature schedule follows A.2.2", "[annealing][thesis]") {
  AnnealingParameters p = thesis_defaults(100, 1);
  CHECK(p.temperature(1) == Approx(1000));
  CHECK(p.temperature(200) == Approx(0.1));
  CHECK(std::log(p.temperature(1) / p.temperature(2)) == Approx(0.046283).margin(1e-6));
  // N pi r_v^2 = 4 pi R^2: r_v = 0.1 at R = 2.5 gives N = 2500 (Table A.6).
  p.points = 2500;
  CHECK(p.vertex_radius() == Approx(0.1));
}

TEST_CASE("Pair energy is the shifted repulsive LJ-8", "[annealing]") {
  CHECK(spheremesh::pair_energy(1.0, 1.0, 3.0, 1.0) == Approx(4 * (1 - std::pow(3.0, -8))));
  CHECK(spheremesh::pair_energy(2.0, 1.0, 3.0, 2.0) == Approx(8 * (std::pow(0.5, 8) - std::pow(3.0, -8))));
  CHECK(spheremesh::pair_energy(3.0, 1.0, 3.0, 1.0) == 0);
  CHECK(spheremesh::pair_energy(2.999999, 1.0, 3.0, 1.0) > 0);
}

TEST_CASE("Linked-cell energy equals the brute-force energy", "[annealing]") {
  for (int n : {4, 37, 300, 1000}) {
    AnnealingParameters p = thesis_defaults(n, 3);
    p.anneals = 3;
    p.sweeps_per_anneal = 2;
    p.t_max = 5, p.t_min = 1;
    const auto result = spheremesh::anneal_on_sphere(p);
    INFO("N = " << n);
    // single-precision energies (annealing.cpp): agreement to 1e-5 relative
    CHECK(result.energy == Approx(spheremesh::total_energy_brute_force(result.points, p)).epsilon(1e-5));
    CHECK(result.attempted == 6LL * n);
    CHECK(result.points.rowwise().norm().maxCoeff() == Approx(2.5).epsilon(1e-14));
    CHECK(result.points.rowwise().norm().minCoeff() == Approx(2.5).epsilon(1e-14));
  }
}

TEST_CASE("Annealing lowers the energy and the acceptance as T falls", "[annealing]") {
  AnnealingParameters p = thesis_defaults(200, 5);
  p.anneals = 20;
  p.sweeps_per_anneal = 20;
  const auto result = spheremesh::anneal_on_sphere(p);
  REQUIRE(result.steps.size() == 20);
  CHECK(result.steps.front().temperature == Approx(1000));
  CHECK(result.steps.back().temperature == Approx(0.1));
  CHECK(result.steps.back().acceptance < result.steps.front().acceptance);
  CHECK(result.steps.back().energy_per_point < result.steps.front().energy_per_point);
}

TEST_CASE("Same seed, same points, another seed, other points", "[annealing]") {
  AnnealingParameters p = thesis_defaults(150, 11);
  p.anneals = 10;
  p.sweeps_per_anneal = 10;
  const auto a = spheremesh::anneal_on_sphere(p), b = spheremesh::anneal_on_sphere(p);
  CHECK(a.points == b.points);
  p.seed = 12;
  const auto c = spheremesh::anneal_on_sphere(p);
  CHECK(a.points != c.points);
}

TEST_CASE("Full default schedule reaches the quality of Table A.5", "[annealing][thesis]") {
  // Table A.5 holds single runs of extreme-value statistics (q_A is a min/max ratio over all
  // vertices), which scatter by about +-0.03 from seed to seed, and its rows are not monotonic
  // in N (N = 625 is below N = 400 and 1111). Each N is held, on the mean of six seeds, to the
  // lower of the thesis rows around it, less that scatter:
  //   N = 100  vs N = 123:         q_A .661  q_theta .729  q .829
  //   N = 500  vs N = 400 and 625: q_A .580  q_theta .605  q .644
  //   N = 1000 vs N = 625 and 1111: the same.
  struct Case {
    int n;
    double q_area, q_angle, q;
  };
  const double scatter = 0.03;
  for (const Case c : {Case{100, 0.661, 0.729, 0.829}, Case{500, 0.580, 0.605, 0.644},
                       Case{1000, 0.580, 0.605, 0.644}}) {
    double q_area = 0, q_angle = 0, q = 0;
    const int seeds = 6;
    for (int seed = 1; seed <= seeds; ++seed) {
      const auto m = annealed_quality(thesis_defaults(c.n, seed));
      q_area += m.q_area / seeds, q_angle += m.q_angle / seeds, q += m.q_radius_ratio / seeds;
    }
    INFO("N = " << c.n << ": mean q_A " << q_area << " q_theta " << q_angle << " q " << q);
    CHECK(q_area >= c.q_area - scatter);
    CHECK(q_angle >= c.q_angle - scatter);
    CHECK(q >= c.q - scatter);
  }
}

TEST_CASE("Quality falls as T_end rises (Table A.6 trend)", "[annealing][thesis]") {
  // Table A.6 at N = 2500: q_A 0.595 (T_end 0.1), 0.381 (10), 0.182 (100), 0.085 (750).
  // Here N = 500 to keep the test short; the same ordering must hold.
  double previous_q_area = 2, previous_q = 2;
  for (double t_end : {0.1, 10.0, 100.0, 750.0}) {
    AnnealingParameters p = thesis_defaults(500, 21);
    p.t_min = t_end;
    const auto q = annealed_quality(p);
    INFO("T_end = " << t_end << ": q_A " << q.q_area << " q " << q.q_radius_ratio);
    CHECK(q.q_area < previous_q_area);
    CHECK(q.q_radius_ratio < previous_q);
    previous_q_area = q.q_area, previous_q = q.q_radius_ratio;
  }
}

TEST_CASE("Bad annealing parameters are refused, all at once", "[annealing]") {
  AnnealingParameters p;
  p.points = 3;
  p.radius = -1;
  p.t_min = 10, p.t_max = 1;
  try {
    p.validate();
    FAIL("no error");
  } catch (const UsageError& e) {
    const std::string what = e.what();
    CHECK(what.find("at least 4") != std::string::npos);
    CHECK(what.find("radius") != std::string::npos);
    CHECK(what.find("T_max") != std::string::npos);
  }
}
