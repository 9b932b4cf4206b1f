#include "shell/svk_membrane.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <cmath>

using namespace cmp::shell;

namespace {

// One triangle in the xy-plane with corners (0,0), (1.3,0.2), (0.4,0.9): no two angles equal.
cmp::mesh::TriMesh scalene() {
  cmp::mesh::TriMesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1.3, 0.2, 0, 0.4, 0.9, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  return m;
}

double area(const cmp::mesh::TriMesh& m) {
  return 0.5 * (m.V.row(1) - m.V.row(0)).cross(m.V.row(2) - m.V.row(0)).norm();
}

// The rest positions mapped by the in-plane deformation gradient Fd, then rotated out of plane.
std::vector<double> deformed(const cmp::mesh::TriMesh& m, const Eigen::Matrix2d& Fd) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, 1.0, -0.4).normalized()).toRotationMatrix();
  std::vector<double> x;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d p = Fd * Eigen::Vector2d(m.V(i, 0), m.V(i, 1));
    const Eigen::Vector3d q = R * Eigen::Vector3d(p.x(), p.y(), 0.0);
    x.insert(x.end(), {q.x(), q.y(), q.z()});
  }
  return x;
}

}  // namespace

TEST_CASE("svk triangle under uniform biaxial stretch has the analytic energy density", "[shell][svk]") {
  const auto m = scalene();
  const MaterialParameters p{2.0e6, 0.3, 0.05};
  const SvkMembrane svk(m, p);
  const double Y = p.stretching_modulus(), nu = p.poisson_ratio;
  for (double s : {0.8, 0.99, 1.01, 1.2, 2.0}) {
    INFO("stretch " << s);
    // G = (s^2 - 1)/2 I: W = (lambda/2)(s^2 - 1)^2 + mu (s^2 - 1)^2/2 = (Y/(4(1 - nu))) (s^2 - 1)^2.
    const double density = Y / (4.0 * (1.0 - nu)) * (s * s - 1) * (s * s - 1);
    CHECK(svk.energy(deformed(m, s * Eigen::Matrix2d::Identity())) == Approx(density * area(m)).epsilon(1e-12));
  }
}

TEST_CASE("svk triangle energy equals the St Venant-Kirchhoff density for any deformation gradient", "[shell][svk]") {
  const auto m = scalene();
  for (double nu : {-0.5, 0.0, 0.25, 0.45, 0.5}) {
    const MaterialParameters p{1.0, nu, 1.0};
    const SvkMembrane svk(m, p);
    const double lambda = nu / (1 - nu * nu), mu = 1.0 / (2 * (1 + nu));
    for (const Eigen::Matrix2d& Fd : {Eigen::Matrix2d{{1.1, 0.0}, {0.0, 1.0}}, Eigen::Matrix2d{{1.0, 0.4}, {0.0, 1.0}},
                                     Eigen::Matrix2d{{0.7, -0.3}, {0.5, 1.6}}}) {
      INFO("nu " << nu << " F " << Fd);
      const Eigen::Matrix2d G = 0.5 * (Fd.transpose() * Fd - Eigen::Matrix2d::Identity());
      const double W = 0.5 * lambda * G.trace() * G.trace() + mu * (G * G).trace();
      CHECK(svk.energy(deformed(m, Fd)) == Approx(W * area(m)).epsilon(1e-12));
    }
  }
}

TEST_CASE("svk refuses bad material parameters and degenerate rest triangles", "[shell][svk]") {
  const auto m = scalene();
  CHECK_THROWS_AS(SvkMembrane(m, {1.0, 0.51, 1.0}), cmp::UsageError);
  CHECK_THROWS_WITH(SvkMembrane(m, {1.0, 0.6, 1.0}), Catch::Contains("svk: Poisson ratio nu = 0.59999") &&
                                                         Catch::Contains("(-1, 0.5]"));
  CHECK_THROWS_WITH(SvkMembrane(m, {1.0, -1.0, 1.0}), Catch::Contains("Poisson ratio"));
  CHECK_THROWS_WITH(SvkMembrane(m, {0.0, 0.3, 1.0}), Catch::Contains("svk: Young's modulus E = 0 must be positive"));
  CHECK_THROWS_WITH(SvkMembrane(m, {NAN, 0.3, 1.0}), Catch::Contains("Young's modulus"));
  CHECK_THROWS_WITH(SvkMembrane(m, {1.0, 0.3, -0.1}), Catch::Contains("svk: thickness t = -0.1"));
  CHECK_NOTHROW(SvkMembrane(m, {1.0, 0.5, 1.0}));
  auto flat = m;
  flat.V.row(2) = 0.5 * (flat.V.row(0) + flat.V.row(1));
  CHECK_THROWS_WITH(SvkMembrane(flat, {1.0, 0.3, 1.0}), Catch::Contains("svk: rest triangle 0 is degenerate"));
  auto bad = m;
  bad.F(0, 2) = 3;
  CHECK_THROWS_WITH(SvkMembrane(bad, {1.0, 0.3, 1.0}), Catch::Contains("face 0 refers to vertex 3"));
}
