// Buckling under external pressure (B.7, Fig. B.10) at test size: a 642-vertex shell, a few
// seconds. Measured values in the comments (the full figure: `make shell-figures`).
#include "shellbench/buckling_run.hpp"

#include "core/errors.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"
#include "spheremesh/subdivision.hpp"

#include <catch2/catch.hpp>

using namespace cmp;
using namespace cmp::shell;
using namespace cmp::shellbench;

namespace {

mesh::TriMesh icosahedral() { return spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, 4, 1.0); }

BucklingResult run(const mesh::TriMesh& m, double gamma, const char* stretching) {
  BucklingCase c;
  c.gamma = gamma;
  c.stretching = stretching;
  const auto r = buckling_run(m, c);
  INFO(stretching << " gamma " << gamma << ": p/p_c in [" << r.stable_pressure << ", " << r.pressure << "]");
  REQUIRE(r.buckled);
  CHECK(r.pressure - r.stable_pressure <= c.resolution);
  CHECK(r.unconverged == 0);
  return r;
}

}  // namespace

TEST_CASE("buckling on the icosahedral mesh: near p_c with the calibrated hinges, closer at lower gamma",
          "[shell][physics][buckling]") {
  const auto m = icosahedral();
  // The SVK membrane keeps the loaded shell spherical: 0.966 p_c at gamma = 1e4. With the
  // `hinge` style (kappa 3x too large) it did not buckle up to 1.6 p_c, and the springs below
  // gave 1.18 instead of 0.82: every band here fails.
  const auto svk = run(m, 1e4, "svk");
  CHECK(svk.pressure > 0.9);
  CHECK(svk.pressure < 1.05);
  // The thesis's springs: 0.822 p_c at gamma = 1e3 and 0.669 at 1e4 (the loaded spring mesh is
  // wavy, rms 0.12-0.16 t, an imperfection: see buckling_run.hpp).
  const auto thick = run(m, 1e3, "springs-seung-nelson");
  const auto thin = run(m, 1e4, "springs-seung-nelson");
  CHECK(thick.pressure > 0.75);
  CHECK(thick.pressure < 0.9);
  CHECK(thin.pressure < thick.pressure - 0.08);
  // Below buckling the volume follows the linear shell, dV/V0 = 4 (p/p_c)/sqrt(gamma) (nu = 1/3):
  // 0.0267 at gamma = 1e4, p = 0.667 p_c; measured 0.0283.
  CHECK(1 - thin.stable_volume == Approx(4 * thin.stable_pressure / 100).epsilon(0.1));
}

TEST_CASE("buckling: a mesh annealed at a high T_end buckles lower than the icosahedral one", "[shell][physics][buckling]") {
  spheremesh::AnnealingParameters a;
  a.points = 642;
  a.t_min = 200;
  a.anneals = 50;
  a.sweeps_per_anneal = 20;
  const auto pts = spheremesh::anneal_on_sphere(a).points;
  const mesh::TriMesh hot{pts, spheremesh::spherical_delaunay(pts)};
  // gamma = 1e3: 0.650 on the T_end = 200 mesh, 0.822 on the icosahedral one.
  const auto disordered = run(hot, 1e3, "springs-seung-nelson");
  CHECK(disordered.pressure < 0.75);
  CHECK(disordered.stable_roughness > 0.13);  // measured 0.148 (icosahedral: 0.121)
}

TEST_CASE("buckling: a bad case is refused before any work", "[shell][buckling]") {
  const auto m = icosahedral();
  BucklingCase c;
  c.gamma = -1;
  CHECK_THROWS_AS(buckling_run(m, c), UsageError);
  c = {};
  c.resolution = 0.1;  // wider than the step
  CHECK_THROWS_WITH(buckling_run(m, c), Catch::Contains("resolution"));
  c = {};
  c.bending = "plates";
  CHECK_THROWS_WITH(buckling_run(m, c), Catch::Contains("unknown bending model"));
}
