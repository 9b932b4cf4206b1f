#include "spheres/hertz_spheres.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "spheres/jamming.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include <omp.h>

using namespace cmp;
using namespace cmp::spheres;


// (Forces against the energy: the force-field harness, tests/forcefield.)
TEST_CASE("Hertzian spheres: pairs touch across periodic boundaries and the forces add up to zero") {
  // Polydisperse spheres, dense enough that most touch several others and many pairs touch
  // through a face of the box.
  const int n = 40;
  const Eigen::Vector3d box(3.0, 3.4, 3.2);
  cmp::Random random(11);
  Eigen::VectorXd radii(n), x(3 * n);
  for (int i = 0; i < n; ++i) radii[i] = 0.45 + 0.15 * random.uniform();
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) x[3 * i + a] = box[a] * random.uniform() - (i % 3 == 0 ? box[a] : 0);  // some outside
  HertzSpheres s(box, radii, HertzMaterial{2.0, 0.3});
  Eigen::VectorXd f;
  s.forces(x, f);
  const auto state = s.evaluate(x);
  REQUIRE(state.contacts.size() > 40);
  int across = 0;
  for (const auto& c : state.contacts) {
    const Eigen::Vector3d direct = x.segment<3>(3 * c.i) - x.segment<3>(3 * c.j);
    across += (direct - c.branch).norm() > 1e-9;
  }
  CHECK(across > 5);
  // Newton's third law: the forces add up to zero.
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) total += f.segment<3>(3 * i);
  CHECK(total.norm() < 1e-12 * f.cwiseAbs().maxCoeff() * n);
}

TEST_CASE("Hertzian spheres: two spheres touching through the box face push apart with the virial pressure") {
  const Eigen::Vector3d box = Eigen::Vector3d::Constant(4.0);
  Eigen::VectorXd radii = Eigen::VectorXd::Constant(2, 0.5);
  Eigen::VectorXd x(6);
  x << 0.1, 2, 2, 3.12, 2, 2;  // minimum image distance 0.98: overlap 0.02
  HertzSpheres s(box, radii, HertzMaterial{});
  Eigen::VectorXd f;
  s.forces(x, f);
  const double F = 4.0 / 3.0 * (2.0 / 3.0) * std::sqrt(0.25) * std::pow(0.02, 1.5);
  CHECK(f[0] == Approx(F));  // sphere 0 is pushed to +x, away from sphere 1's image at x = -0.88
  CHECK(f[3] == Approx(-F));
  CHECK(f.segment<2>(1).norm() == 0);
  const auto state = s.evaluate(x);
  REQUIRE(state.contacts.size() == 1);
  CHECK(state.contacts[0].overlap == Approx(0.02));
  CHECK(state.pressure == Approx(0.98 * F / (3 * 64.0)));
  CHECK(state.pressure > 0);
  CHECK(state.energy == Approx(0.4 * F * 0.02));
}

TEST_CASE("Hertzian spheres: the pair list follows moves and radius changes") {
  const Eigen::Vector3d box = Eigen::Vector3d::Constant(10.0);
  Eigen::VectorXd radii = Eigen::VectorXd::Constant(2, 0.5);
  Eigen::VectorXd x(6);
  x << 1, 1, 1, 3, 1, 1;  // apart
  HertzSpheres s(box, radii, HertzMaterial{});
  Eigen::VectorXd f;
  s.forces(x, f);
  CHECK(f.norm() == 0);
  x[3] = 1.9;  // moved far beyond the skin: now overlapping
  s.forces(x, f);
  CHECK(f[0] < 0);
  x[3] = 3;
  s.set_radii(Eigen::VectorXd::Constant(2, 1.05));  // grown into contact
  s.forces(x, f);
  CHECK(f[0] < 0);
  CHECK(s.list_builds() >= 3);
}

TEST_CASE("Hertzian spheres: a sphere wider than half the box is refused") {
  Eigen::VectorXd radii = Eigen::VectorXd::Constant(2, 0.6);
  HertzSpheres s(Eigen::Vector3d::Constant(2.0), radii, HertzMaterial{});
  Eigen::VectorXd x = Eigen::VectorXd::Zero(6), f;
  CHECK_THROWS_AS(s.forces(x, f), cmp::ComputationError);
  CHECK_THROWS_AS(HertzSpheres(Eigen::Vector3d(1, 0, 1), radii, HertzMaterial{}), cmp::UsageError);
  CHECK_THROWS_AS(HertzSpheres(Eigen::Vector3d::Ones(), radii, HertzMaterial{1, 1.0}), cmp::UsageError);
}

TEST_CASE("Hertzian spheres: the chunked parallel force loop of large systems sums every contact, the same on any thread count") {
  // Above kParallelForceSpheres the pair list is cut into fixed chunks summed into separate
  // buffers; the result must be the forces of the contacts, bit for bit the same on 1 and 2
  // threads.
  const int n = HertzSpheres::kParallelForceSpheres + 500;
  const double side = jamming_box_side(n);
  cmp::Random random(3);
  Eigen::VectorXd x(3 * n);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = side * random.uniform();
  HertzSpheres s(Eigen::Vector3d::Constant(side), Eigen::VectorXd::Constant(n, 0.5), HertzMaterial{});
  Eigen::VectorXd f1, f2;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  s.forces(x, f1);
  omp_set_num_threads(2);
  s.forces(x, f2);
  omp_set_num_threads(threads);
  CHECK(f1 == f2);
  // The same forces from the contact list, pair by pair.
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(3 * n);
  const auto state = s.evaluate(x);
  REQUIRE(state.contacts.size() > static_cast<std::size_t>(n));
  for (const auto& c : state.contacts) {
    const Eigen::Vector3d fij = c.force * c.branch.normalized();
    expected.segment<3>(3 * c.i) += fij;
    expected.segment<3>(3 * c.j) -= fij;
  }
  CHECK((f1 - expected).cwiseAbs().maxCoeff() < 1e-12 * expected.cwiseAbs().maxCoeff());
}
