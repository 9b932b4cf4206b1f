#include "voxel/porosity.hpp"

#include "spheremesh/subdivision.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::voxel;

TEST_CASE("lens_volume: limits and a numeric check", "[voxel][porosity]") {
  CHECK(lens_volume(1, 1, 2) == 0);
  CHECK(lens_volume(1, 1, 0) == Approx(4 * M_PI / 3));
  CHECK(lens_volume(1, 0.5, 0.2) == Approx(4 * M_PI / 3 * 0.125));  // small one inside
  // equal spheres: pi (4r + d)(2r - d)^2 / 12
  CHECK(lens_volume(1, 1, 1) == Approx(M_PI * 5 * 1 / 12));
  // unequal, against a midpoint-rule integral over slices along the axis
  const double r1 = 1.0, r2 = 0.7, d = 1.2;
  double sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = -r1 + (i + 0.5) * (2 * r1) / n;
    const double a1 = r1 * r1 - x * x, a2 = r2 * r2 - (x - d) * (x - d);
    if (a1 > 0 && a2 > 0) sum += M_PI * std::min(a1, a2) * (2 * r1) / n;
  }
  CHECK(lens_volume(r1, r2, d) == Approx(sum).epsilon(1e-6));
}

TEST_CASE("sphere_volumes: total and periodic pair overlaps", "[voxel][porosity]") {
  cmp::mesh::VertexMatrix c(2, 3);
  c << 0.1, 0.5, 0.5, 0.9, 0.5, 0.5;  // 0.2 apart through the periodic x face
  const Eigen::VectorXd r = Eigen::VectorXd::Constant(2, 0.15);
  const auto v = sphere_volumes(c, r, Eigen::Vector3d::Ones(), {true, true, true});
  CHECK(v.total == Approx(2 * 4 * M_PI / 3 * std::pow(0.15, 3)));
  CHECK(v.pair_overlap == Approx(lens_volume(0.15, 0.15, 0.2)));
  CHECK(sphere_volumes(c, r, Eigen::Vector3d::Ones(), {false, true, true}).pair_overlap == 0);
}

TEST_CASE("shell_volumes of two sphere meshes and voxel_porosity", "[voxel][porosity]") {
  const auto a = cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 3, 1.0);
  const auto b = cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 3, 0.5);
  const long na = a.V.rows();
  cmp::mesh::VertexMatrix V(na + b.V.rows(), 3);
  V << a.V, b.V;
  cmp::mesh::FaceMatrix F(a.F.rows() + b.F.rows(), 3);
  F << b.F.array() + na, a.F;  // faces in any order
  const auto vols = shell_volumes(V, F, {0, static_cast<int>(na), static_cast<int>(V.rows())});
  REQUIRE(vols.size() == 2);
  CHECK(vols[0] == Approx(4 * M_PI / 3).epsilon(0.04));  // chordal mesh (level 3): 3.4% less
  CHECK(vols[0] < 4 * M_PI / 3);
  CHECK(vols[1] == Approx(vols[0] / 8));
  CHECK(voxel_porosity({1, 0, 0, 1}) == 0.5);
  CHECK(voxel_porosity({}) == 0);
}
