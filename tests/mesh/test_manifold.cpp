#include "mesh/manifold.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

namespace {
ManifoldReport report(const TriMesh& m) { return manifold_report(m.F, static_cast<int>(m.V.rows())); }
}  // namespace

TEST_CASE("manifold_report of closed meshes: Euler characteristic 2 for spheres, 0 for a torus", "[mesh][manifold]") {
  struct Case {
    TriMesh m;
    long v, e, f, chi;
  };
  for (const auto& c : {Case{fx::unit_cube(), 8, 18, 12, 2}, Case{fx::regular_tetrahedron(1), 4, 6, 4, 2},
                        Case{fx::octahedron(), 6, 12, 8, 2}, Case{fx::uv_sphere(10, 5, 1), 42, 120, 80, 2},
                        Case{fx::torus(9, 4, 2, 1), 36, 108, 72, 0}}) {
    const ManifoldReport r = report(c.m);
    CHECK(r.vertices == c.v);
    CHECK(r.edges == c.e);
    CHECK(r.faces == c.f);
    CHECK(r.euler_characteristic == c.chi);
    CHECK(euler_characteristic(c.m.F, static_cast<int>(c.m.V.rows())) == c.chi);
    CHECK(r.unused_vertices == 0);
    CHECK(r.boundary_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.degenerate_faces == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.closed_manifold());
    CHECK(r.consistently_oriented());
  }
}

TEST_CASE("manifold_report of a single triangle: three boundary edges", "[mesh][manifold]") {
  const ManifoldReport r = report(fx::single_triangle());
  CHECK(r.euler_characteristic == 1);
  CHECK(r.boundary_edges == 3);
  CHECK_FALSE(r.closed_manifold());
  CHECK(r.consistently_oriented());
}

TEST_CASE("manifold_report counts unused vertices outside the Euler characteristic", "[mesh][manifold]") {
  auto c = fx::unit_cube();
  c.V.conservativeResize(10, 3);
  c.V.bottomRows(2).setZero();
  const ManifoldReport r = report(c);
  CHECK(r.vertices == 10);
  CHECK(r.unused_vertices == 2);
  CHECK(r.euler_characteristic == 2);
  CHECK(r.closed_manifold());  // unused vertices do not break it
}

TEST_CASE("manifold_report: one flipped face misorients its three edges", "[mesh][manifold]") {
  auto s = fx::uv_sphere(10, 5, 1);
  fx::flip_face(s.F, 17);
  const ManifoldReport r = report(s);
  CHECK(r.misoriented_edges == 3);
  CHECK_FALSE(r.consistently_oriented());
  CHECK(r.closed_manifold());
  fx::flip_face(s.F, 18);  // its neighbour across a rung: that edge agrees again, two more do not
  CHECK(report(s).misoriented_edges == 4);
  auto t = fx::torus(9, 4, 2, 1);
  t.F = fx::flipped_all(t.F);  // inward, but consistent
  CHECK(report(t).misoriented_edges == 0);
}

TEST_CASE("manifold_report of three triangles on one edge", "[mesh][manifold]") {
  const ManifoldReport r = report(fx::three_triangles_on_one_edge());
  CHECK(r.edges == 7);
  CHECK(r.nonmanifold_edges == 1);
  CHECK(r.boundary_edges == 6);
  CHECK(r.euler_characteristic == 5 - 7 + 3);
  CHECK(r.misoriented_edges == 0);  // only edges with exactly two faces count
  CHECK_FALSE(r.closed_manifold());
}

TEST_CASE("manifold_report of a Moebius strip: one boundary loop, one seam misoriented", "[mesh][manifold]") {
  const int n = 12;
  const ManifoldReport r = report(fx::moebius_strip(n, 2, 0.5));
  CHECK(r.vertices == 2 * n);
  CHECK(r.edges == 4 * n);
  CHECK(r.euler_characteristic == 0);
  CHECK(r.boundary_edges == 2 * n);
  CHECK(r.nonmanifold_edges == 0);
  CHECK(r.misoriented_edges == 1);  // no orientation gets it below one
}

TEST_CASE("manifold_report counts degenerate faces and describe() says it all", "[mesh][manifold]") {
  auto c = fx::unit_cube();
  c.F.conservativeResize(13, 3);
  c.F.row(12) << 3, 3, 5;
  const ManifoldReport r = report(c);
  CHECK(r.degenerate_faces == 1);
  CHECK_FALSE(r.closed_manifold());
  CHECK(r.describe() ==
        "8 vertices, 19 edges, 13 faces, Euler characteristic 2; 0 unused vertices, 0 boundary edges, "
        "0 non-manifold edges, 1 degenerate faces, 0 misoriented edges");
  CHECK_THROWS_AS(manifold_report(c.F, 7), std::out_of_range);
  CHECK_THROWS_AS(euler_characteristic(c.F, 7), std::out_of_range);
}
