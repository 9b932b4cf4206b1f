#include "shell/turgor_pressure.hpp"

#include "shell_fixtures.hpp"

#include "core/errors.hpp"
#include "mesh/enclosed_volume.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;

TEST_CASE("turgor energy is minus Pi times the enclosed volume", "[shell][turgor]") {
  const auto m = fx::perturbed_icosphere(3, 0.03, 5, 2.0);
  const TurgorPressure p(m, {0.75});
  const auto x = fx::state(m.V);
  CHECK(p.energy(x) == Approx(-0.75 * cmp::mesh::enclosed_volume(m.V, m.F)).epsilon(1e-12));
  CHECK(signed_volume(x, std::vector<int>(m.F.data(), m.F.data() + m.F.size())) > 0);
}

TEST_CASE("turgor gradient is minus Pi times a third of the incident area vectors and sums to zero",
          "[shell][turgor]") {
  const auto m = fx::perturbed_icosphere(3, 0.05, 9, 1.5);
  const double Pi = 3.0;
  const TurgorPressure p(m, {Pi});
  const auto x = fx::state(m.V);
  std::vector<double> g(x.size(), 0.0);
  p.add_gradient(x, g);
  // -Pi times the area vector A_T n_T of each face, a third to each corner.
  std::vector<Eigen::Vector3d> expect(m.V.rows(), Eigen::Vector3d::Zero());
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const Eigen::Vector3d area_vector = 0.5 * (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) expect[m.F(f, k)] -= Pi * area_vector / 3;
  }
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double outward = 0;
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    const Eigen::Vector3d gi(g[3 * i], g[3 * i + 1], g[3 * i + 2]);
    CHECK((gi - expect[i]).norm() < 1e-12 * expect[i].norm() + 1e-14);
    total += gi;
    outward += -gi.dot(Eigen::Vector3d(m.V.row(i)).normalized());
  }
  CHECK(total.norm() < 1e-12);
  // The force -g pushes outward for Pi > 0, and its work on a radial dilation is Pi dV:
  // sum_i F_i . x_i = 3 Pi V.
  CHECK(outward > 0);
  double work = 0;
  for (std::size_t i = 0; i < x.size(); ++i) work -= g[i] * x[i];
  CHECK(work == Approx(3 * Pi * cmp::mesh::enclosed_volume(m.V, m.F)).epsilon(1e-12));
}

TEST_CASE("turgor refuses a non-finite pressure and faces outside the mesh", "[shell][turgor]") {
  const auto m = fx::perturbed_icosphere(1, 0.0, 1);
  CHECK_THROWS_WITH(TurgorPressure(m, {INFINITY}), Catch::Contains("turgor: pressure Pi = inf must be finite"));
  auto bad = m;
  bad.F(3, 1) = -2;
  CHECK_THROWS_AS(TurgorPressure(bad, {1.0}), cmp::UsageError);
  CHECK_NOTHROW(TurgorPressure(m, {-2.0}));  // external pressure
}

TEST_CASE("turgor refuses an open mesh and an inward-oriented one", "[shell][turgor]") {
  const auto m = fx::perturbed_icosphere(2, 0.02, 4);
  auto open = m;
  open.F.conservativeResize(m.F.rows() - 1, 3);
  CHECK_THROWS_WITH(TurgorPressure(open, {1.0}), Catch::Contains("turgor: the mesh must be closed") &&
                                                     Catch::Contains("boundary"));
  auto inward = m;
  inward.F.col(1).swap(inward.F.col(2));
  CHECK_THROWS_WITH(TurgorPressure(inward, {1.0}), Catch::Contains("turgor: the faces are oriented inward"));
  auto mixed = m;
  std::swap(mixed.F(0, 1), mixed.F(0, 2));
  CHECK_THROWS_WITH(TurgorPressure(mixed, {1.0}), Catch::Contains("consistently oriented"));
}
