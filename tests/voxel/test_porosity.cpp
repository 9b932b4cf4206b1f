#include "packing/shell_volumes.hpp"
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
  const auto vols = cmp::packing::shell_volumes(V, F, {0, static_cast<int>(na), static_cast<int>(V.rows())});
  REQUIRE(vols.size() == 2);
  CHECK(vols[0] == Approx(4 * M_PI / 3).epsilon(0.04));  // chordal mesh (level 3): 3.4% less
  CHECK(vols[0] < 4 * M_PI / 3);
  CHECK(vols[1] == Approx(vols[0] / 8));
  CHECK(voxel_porosity({1, 0, 0, 1}) == 0.5);
  CHECK(voxel_porosity({}) == 0);
}

TEST_CASE("three_spheres_intersect decides a common point exactly", "[voxel][porosity]") {
  // unit spheres on an equilateral triangle of side s meet iff the circumradius s / sqrt 3 < 1
  auto tri = [](double s) {
    return three_spheres_intersect(Eigen::Vector3d(0, 0, 0), 1, Eigen::Vector3d(s, 0, 0), 1,
                                   Eigen::Vector3d(s / 2, s * std::sqrt(3.0) / 2, 0), 1);
  };
  CHECK(tri(std::sqrt(3.0) * (1 - 1e-9)));
  CHECK(!tri(std::sqrt(3.0) * (1 + 1e-9)));
  // pairwise overlapping on a line but the outer two apart: no common point
  CHECK(!three_spheres_intersect(Eigen::Vector3d(0, 0, 0), 1, Eigen::Vector3d(1.9, 0, 0), 1,
                                 Eigen::Vector3d(3.8, 0, 0), 1));
  // a small sphere inside the lens of two others; collinear centres
  CHECK(three_spheres_intersect(Eigen::Vector3d(0, 0, 0), 1, Eigen::Vector3d(1.5, 0, 0), 1,
                                Eigen::Vector3d(0.75, 0, 0), 0.01));
  // a small sphere beside the lens: overlaps each of the two but not their lens
  CHECK(!three_spheres_intersect(Eigen::Vector3d(0, 0, 0), 1, Eigen::Vector3d(1.8, 0, 0), 1,
                                 Eigen::Vector3d(0.9, 0.6, 0), 0.15));
}

TEST_CASE("sphere_volumes says when the pair-lens correction is exact", "[voxel][porosity]") {
  // simple cubic array (4 x 4 x 4 cells of side 1): no point is in three spheres while r < 1/sqrt 2
  cmp::mesh::VertexMatrix c(64, 3);
  for (int i = 0; i < 64; ++i) c.row(i) << (i & 3), (i >> 2 & 3), (i >> 4 & 3);
  const Eigen::Vector3d box = Eigen::Vector3d::Constant(4.0);
  const double rc = 1 / std::sqrt(2.0);
  const auto below = sphere_volumes(c, Eigen::VectorXd::Constant(64, rc * 0.999), box, {true, true, true});
  CHECK(below.pair_correction_exact());
  CHECK(below.pair_overlap == Approx(64 * 3 * lens_volume(rc * 0.999, rc * 0.999, 1)));
  // in 2 x 2 x 2 cells each neighbour is also met through the next image: one lens is missed
  cmp::mesh::VertexMatrix c8(8, 3);
  for (int i = 0; i < 8; ++i) c8.row(i) << (i & 1), (i >> 1 & 1), (i >> 2 & 1);
  const auto v8 = sphere_volumes(c8, Eigen::VectorXd::Constant(8, 0.6), Eigen::Vector3d::Constant(2.0), {true, true, true});
  CHECK(v8.image_overlaps == 12);
  CHECK(v8.pair_overlap == Approx(24 * lens_volume(0.6, 0.6, 1)));  // both lenses of each of the 12 pairs
  const auto above = sphere_volumes(c, Eigen::VectorXd::Constant(64, rc * 1.001), box, {true, true, true});
  CHECK(above.triple_overlaps > 0);
  CHECK(above.image_overlaps == 0);
  CHECK(!above.pair_correction_exact());
  // one sphere in a unit cell: it overlaps its own image once 2 r > 1
  cmp::mesh::VertexMatrix one(1, 3);
  one << 0.5, 0.5, 0.5;
  CHECK(sphere_volumes(one, Eigen::VectorXd::Constant(1, 0.49), Eigen::Vector3d::Ones(), {true, true, true}).pair_correction_exact());
  CHECK(sphere_volumes(one, Eigen::VectorXd::Constant(1, 0.51), Eigen::Vector3d::Ones(), {true, true, true}).image_overlaps == 3);
  CHECK(sphere_volumes(one, Eigen::VectorXd::Constant(1, 0.51), Eigen::Vector3d::Ones(), {true, false, false}).image_overlaps == 1);
  // its lenses with its own images are counted (once per pair of images): one sphere of r = 0.6
  // in a unit cell fills the ball less six caps of height r - 1/2, i.e. 3 lenses, exactly
  const auto self = sphere_volumes(one, Eigen::VectorXd::Constant(1, 0.6), Eigen::Vector3d::Ones(), {true, true, true});
  CHECK(self.pair_overlap == Approx(3 * lens_volume(0.6, 0.6, 1)));
  CHECK(1 - (self.total - self.pair_overlap) > 0);
  // two spheres 0.5 apart in a unit cell overlap through both images along x
  cmp::mesh::VertexMatrix two(2, 3);
  two << 0.25, 0.5, 0.5, 0.75, 0.5, 0.5;
  CHECK(sphere_volumes(two, Eigen::VectorXd::Constant(2, 0.3), Eigen::Vector3d::Ones(), {true, true, true}).image_overlaps == 1);
  CHECK(sphere_volumes(two, Eigen::VectorXd::Constant(2, 0.24), Eigen::Vector3d::Ones(), {true, true, true}).pair_correction_exact());
}
