#include "spheres/hertz_spheres.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "spheres/jamming.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include <omp.h>

using namespace cmp::spheres;

namespace {
double energy_at(HertzSpheres& s, const Eigen::VectorXd& x) { return s.evaluate(x).energy; }

// Central differences of the energy, coordinate by coordinate.
Eigen::VectorXd numerical_forces(HertzSpheres& s, Eigen::VectorXd x, double step) {
  Eigen::VectorXd f(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double x0 = x[k];
    x[k] = x0 + step;
    const double up = energy_at(s, x);
    x[k] = x0 - step;
    const double down = energy_at(s, x);
    x[k] = x0;
    f[k] = -(up - down) / (2 * step);
  }
  return f;
}
}  // namespace

TEST_CASE("Hertz law: E* = 2/3 for E = 1, nu = 0.5, and the force is minus the energy's derivative") {
  const HertzMaterial m;
  CHECK(m.effective_modulus() == Approx(2.0 / 3.0));
  CHECK(effective_radius(0.5, 0.5) == Approx(0.25));
  const double c = hertz_prefactor(m, 0.5, 0.5);
  CHECK(c == Approx(4.0 / 3.0 * 2.0 / 3.0 * 0.5));
  const double h = 0.01, dh = 1e-7;
  CHECK(hertz_force(c, h) == Approx((hertz_energy(c, h + dh) - hertz_energy(c, h - dh)) / (2 * dh)).epsilon(1e-8));
  CHECK(hertz_force(c, -0.1) == 0);
  CHECK(hertz_energy(c, 0) == 0);
}

TEST_CASE("Hertzian spheres: forces are minus the numerical gradient, across periodic boundaries") {
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
  const Eigen::VectorXd g = numerical_forces(s, x, 1e-6);
  CHECK((f - g).cwiseAbs().maxCoeff() < 1e-7 * f.cwiseAbs().maxCoeff());
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
