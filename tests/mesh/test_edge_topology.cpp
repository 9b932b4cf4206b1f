#include "mesh/edge_topology.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

namespace {
// Invariants every EdgeTopology must satisfy, checked against the faces themselves.
void check_invariants(const FaceMatrix& F, const EdgeTopology& t) {
  const Eigen::Index E = t.edges.rows();
  REQUIRE(t.edge_faces.rows() == E);
  REQUIRE(static_cast<Eigen::Index>(t.edge_face_counts.size()) == E);
  for (Eigen::Index e = 0; e < E; ++e) {
    CHECK(t.edges(e, 0) < t.edges(e, 1));
    if (e > 0)
      CHECK((t.edges(e - 1, 0) < t.edges(e, 0) || (t.edges(e - 1, 0) == t.edges(e, 0) && t.edges(e - 1, 1) < t.edges(e, 1))));
    // count and first two faces, by a direct scan of F
    std::vector<int> faces;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      std::set<int> corners{F(f, 0), F(f, 1), F(f, 2)};
      if (corners.count(t.edges(e, 0)) && corners.count(t.edges(e, 1))) faces.push_back(static_cast<int>(f));
    }
    CHECK(t.edge_face_counts[e] == static_cast<int>(faces.size()));
    CHECK(t.edge_faces(e, 0) == faces[0]);
    CHECK(t.edge_faces(e, 1) == (faces.size() > 1 ? faces[1] : -1));
  }
}
}  // namespace

TEST_CASE("edge_topology of closed meshes: E = 3F/2, every edge in two faces", "[mesh][edge_topology]") {
  struct Case {
    TriMesh m;
    long edges;
  };
  for (const auto& c : {Case{fx::unit_cube(), 18}, Case{fx::regular_tetrahedron(1), 6}, Case{fx::octahedron(), 12},
                        Case{fx::uv_sphere(8, 4, 1), 72},
                        Case{fx::torus(7, 5, 2, 1), 3 * 35}}) {
    const EdgeTopology t = edge_topology(c.m.F);
    CHECK(t.edges.rows() == c.edges);
    for (int n : t.edge_face_counts) CHECK(n == 2);
    check_invariants(c.m.F, t);
  }
}

TEST_CASE("edge_topology of open and non-manifold meshes", "[mesh][edge_topology]") {
  const auto single = fx::single_triangle();
  const EdgeTopology t1 = edge_topology(single.F);
  REQUIRE(t1.edges.rows() == 3);
  CHECK(t1.edges.row(0) == Eigen::RowVector2i(0, 1));
  CHECK(t1.edges.row(1) == Eigen::RowVector2i(0, 2));
  CHECK(t1.edges.row(2) == Eigen::RowVector2i(1, 2));
  for (int e = 0; e < 3; ++e) {
    CHECK(t1.edge_face_counts[e] == 1);
    CHECK(t1.edge_faces(e, 0) == 0);
    CHECK(t1.edge_faces(e, 1) == -1);
  }

  const auto fan = fx::three_triangles_on_one_edge();
  const EdgeTopology t3 = edge_topology(fan.F);
  REQUIRE(t3.edges.rows() == 7);
  CHECK(t3.edges.row(0) == Eigen::RowVector2i(0, 1));
  CHECK(t3.edge_face_counts[0] == 3);
  CHECK(t3.edge_faces.row(0) == Eigen::RowVector2i(0, 1));  // the first two of faces 0, 1, 2
  check_invariants(fan.F, t3);

  const auto strip = fx::moebius_strip(9, 2, 0.5);
  const EdgeTopology tm = edge_topology(strip.F);
  CHECK(tm.edges.rows() == 4 * 9);
  check_invariants(strip.F, tm);
}

TEST_CASE("edge_topology leaves out the self-edge of a degenerate face", "[mesh][edge_topology]") {
  FaceMatrix F(1, 3);
  F << 2, 2, 5;
  const EdgeTopology t = edge_topology(F);
  REQUIRE(t.edges.rows() == 1);
  CHECK(t.edges.row(0) == Eigen::RowVector2i(2, 5));
  CHECK(t.edge_face_counts[0] == 2);
  CHECK(edge_topology(FaceMatrix(0, 3)).edges.rows() == 0);
}

TEST_CASE("vertex_adjacency: sorted rows, empty for unused vertices", "[mesh][edge_topology]") {
  const auto o = fx::octahedron();
  const VertexAdjacency a = vertex_adjacency(o.F, 7);  // vertex 6 is in no face
  REQUIRE(a.offsets.size() == 8);
  CHECK(a.neighbours.size() == 24);
  const std::vector<std::vector<int>> expected = {{2, 3, 4, 5}, {2, 3, 4, 5}, {0, 1, 4, 5}, {0, 1, 4, 5},
                                                  {0, 1, 2, 3}, {0, 1, 2, 3}, {}};
  for (int i = 0; i < 7; ++i) {
    const std::vector<int> row(a.neighbours.begin() + a.offsets[i], a.neighbours.begin() + a.offsets[i + 1]);
    CHECK(row == expected[i]);
  }

  const auto s = fx::uv_sphere(10, 6, 1);
  const VertexAdjacency b = vertex_adjacency(s.F, static_cast<int>(s.V.rows()));
  CHECK(b.offsets[1] - b.offsets[0] == 10);  // the north pole sees its ring
  // first ring: the pole, two ring neighbours, two below; then valence 6 down to the last ring
  for (int i = 1; i <= 10; ++i) CHECK(b.offsets[i + 1] - b.offsets[i] == 5);
  for (int i = 11; i <= 40; ++i) CHECK(b.offsets[i + 1] - b.offsets[i] == 6);
  CHECK(b.offsets.back() == 2 * 3 * s.F.rows() / 2);
}

TEST_CASE("vertex_adjacency rejects an index out of range", "[mesh][edge_topology]") {
  const auto o = fx::octahedron();
  CHECK_THROWS_AS(vertex_adjacency(o.F, 5), std::out_of_range);
}
