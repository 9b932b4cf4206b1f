#include "shell/edge_springs.hpp"

#include "shell_fixtures.hpp"

#include "core/errors.hpp"
#include "spheremesh/subdivision.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;

namespace {
// The icosahedron: 20 equilateral triangles, 30 edges, every edge between two triangles.
cmp::mesh::TriMesh icosahedron(double radius) {
  return cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 1, radius);
}
}  // namespace

TEST_CASE("spring constants on an equilateral mesh follow B.22 B.26 and B.27", "[shell][springs]") {
  const auto m = icosahedron(1.7);
  const double a = (m.V.row(m.F(0, 1)) - m.V.row(m.F(0, 0))).norm();
  for (double nu : {1.0 / 3.0, 0.0, 0.2, 0.45}) {
    INFO("nu " << nu);
    const MaterialParameters p{5.0, nu, 0.2};
    const double Y = p.stretching_modulus();
    for (double k : edge_spring_constants(m, p, SpringConstants::SeungNelson))
      CHECK(k == Approx(std::sqrt(3.0) * Y / 2).epsilon(1e-14));
    // B.26 with A_0 = 20 (sqrt(3)/4) a^2 and sum L^2 = 30 a^2.
    const double kot = 2 * Y / (1 - nu) * (20 * std::sqrt(3.0) / 4 * a * a) / (30 * a * a);
    for (double k : edge_spring_constants(m, p, SpringConstants::Kot)) CHECK(k == Approx(kot).epsilon(1e-12));
    // B.27 on each of the two equilateral triangles: Y/(1+nu) sqrt(3)/4 + Y nu/(1-nu^2) / (2 sqrt(3)).
    const double vg = 2 * (Y / (1 + nu) * std::sqrt(3.0) / 4 + Y * nu / (1 - nu * nu) / (2 * std::sqrt(3.0)));
    for (double k : edge_spring_constants(m, p, SpringConstants::VanGelder)) CHECK(k == Approx(vg).epsilon(1e-12));
  }
  // At nu = 1/3 the three rules agree: k = sqrt(3) Y / 2, i.e. Y = 2k/sqrt(3).
  const MaterialParameters third{5.0, 1.0 / 3.0, 0.2};
  const double k_sn = edge_spring_constants(m, third, SpringConstants::SeungNelson)[0];
  CHECK(edge_spring_constants(m, third, SpringConstants::Kot)[0] == Approx(k_sn).epsilon(1e-12));
  CHECK(edge_spring_constants(m, third, SpringConstants::VanGelder)[0] == Approx(k_sn).epsilon(1e-12));
  CHECK(2 * k_sn / std::sqrt(3.0) == Approx(third.stretching_modulus()).epsilon(1e-14));
}

TEST_CASE("seung-nelson springs under isotropic stretch store the energy of a sheet with Y = 2k over sqrt(3)",
          "[shell][springs]") {
  // Scaling the equilateral mesh by (1 + eps) stores (1/2) k eps^2 sum L^2 in the springs; the
  // continuum sheet with nu = 1/3 stores 2 K_B eps^2 A_0 = Y/(1 - nu) eps^2 A_0 (B.24).
  const auto m = icosahedron(1.0);
  const MaterialParameters p{4.0, 1.0 / 3.0, 0.5};
  const EdgeSprings springs(m, p, SpringConstants::SeungNelson, "springs-seung-nelson");
  const double a = springs.rest_lengths()[0];
  const double A0 = 20 * std::sqrt(3.0) / 4 * a * a;
  for (double eps : {1e-3, 0.05}) {
    auto x = fx::state(m.V);
    for (double& v : x) v *= 1 + eps;
    const double Y = 2 * springs.spring_constants()[0] / std::sqrt(3.0);
    CHECK(springs.energy(x) == Approx(Y / (1 - 1.0 / 3.0) * eps * eps * A0).epsilon(1e-12));
  }
}

TEST_CASE("kot springs under isotropic stretch store 2 K_B eps^2 A_0 on any mesh", "[shell][springs]") {
  // B.24-B.26: the condition that fixes k, exact for harmonic springs under uniform scaling.
  const auto m = fx::perturbed_icosphere(2, 0.05, 11);
  const MaterialParameters p{3.0, 0.25, 0.1};
  const EdgeSprings springs(m, p, SpringConstants::Kot, "springs-kot");
  double A0 = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    A0 += 0.5 * (m.V.row(m.F(f, 1)) - m.V.row(m.F(f, 0))).cross(m.V.row(m.F(f, 2)) - m.V.row(m.F(f, 0))).norm();
  const double eps = 0.02;
  auto x = fx::state(m.V);
  for (double& v : x) v *= 1 + eps;
  CHECK(springs.energy(x) == Approx(p.stretching_modulus() / (1 - p.poisson_ratio) * eps * eps * A0).epsilon(1e-12));
}

TEST_CASE("edge springs refuse bad parameters with the style name", "[shell][springs]") {
  const auto m = icosahedron(1.0);
  CHECK_THROWS_WITH(EdgeSprings(m, {-1.0, 0.3, 1.0}, SpringConstants::Kot, "springs-kot"),
                    Catch::Contains("springs-kot: Young's modulus E = -1"));
  CHECK_THROWS_AS(EdgeSprings(m, {1.0, 0.7, 1.0}, SpringConstants::VanGelder, "springs-van-gelder"), cmp::UsageError);
}
