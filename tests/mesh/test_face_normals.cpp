#include "mesh/face_normals.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

TEST_CASE("face_normals of the unit cube are the outward axis directions", "[mesh][face_normals]") {
  const auto m = fx::unit_cube();
  const VertexMatrix n = face_normals(m.V, m.F);
  const double expected[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (int f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) CHECK(n(f, k) == expected[f / 2][k]);
}

TEST_CASE("face_normals of the octahedron point into their octant", "[mesh][face_normals]") {
  const auto m = fx::octahedron();
  const VertexMatrix n = face_normals(m.V, m.F);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::RowVector3d centroid = (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3;
    for (int k = 0; k < 3; ++k) CHECK(n(f, k) == Approx(centroid[k] > 0 ? 1 / std::sqrt(3.0) : -1 / std::sqrt(3.0)));
  }
}

TEST_CASE("face_normals are unit and outward on a UV sphere and a tetrahedron", "[mesh][face_normals]") {
  for (const auto& m : {fx::uv_sphere(16, 8, 1.5), fx::regular_tetrahedron(2.0)}) {
    const VertexMatrix n = face_normals(m.V, m.F);
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      const Eigen::RowVector3d centroid = (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3;
      CHECK(n.row(f).norm() == Approx(1.0).epsilon(1e-15));
      // outward: nearly parallel to the centroid direction on these round meshes
      CHECK(n.row(f).dot(centroid.normalized()) > 0.9);
    }
  }
}

TEST_CASE("face_normals: a flipped face has the opposite normal, a degenerate one zero", "[mesh][face_normals]") {
  auto m = fx::single_triangle();
  CHECK(face_normals(m.V, m.F).row(0) == Eigen::RowVector3d(0, 0, 1));
  fx::flip_face(m.F, 0);
  CHECK(face_normals(m.V, m.F).row(0) == Eigen::RowVector3d(0, 0, -1));
  m.V.row(2) = m.V.row(1) * 2;  // collinear
  CHECK(face_normals(m.V, m.F).row(0) == Eigen::RowVector3d::Zero());
}
