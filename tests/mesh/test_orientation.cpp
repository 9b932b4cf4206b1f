#include "mesh/orientation.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "mesh/enclosed_volume.hpp"
#include "mesh/manifold.hpp"
#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

namespace {
// Flips each face with probability p; returns how many.
long flip_randomly(FaceMatrix& F, double p, std::uint64_t seed) {
  cmp::Random random(seed);
  long flipped = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (random.uniform() < p) {
      fx::flip_face(F, f);
      ++flipped;
    }
  return flipped;
}
}  // namespace

TEST_CASE("orient_outward leaves an outward mesh alone", "[mesh][orientation]") {
  for (const auto& m : {fx::unit_cube(), fx::octahedron(), fx::uv_sphere(12, 6, 1), fx::torus(12, 6, 2, 0.5)}) {
    FaceMatrix F = m.F;
    CHECK(orient_outward(m.V, F) == 0);
    CHECK(F == m.F);
  }
}

TEST_CASE("orient_outward repairs randomly flipped closed meshes and counts the flips", "[mesh][orientation]") {
  for (const auto& m : {fx::uv_sphere(16, 8, 1), fx::torus(20, 8, 2, 0.5), fx::unit_cube()})
    for (double p : {0.05, 0.3, 0.7, 1.0})
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        FaceMatrix F = m.F;
        const long flipped = flip_randomly(F, p, seed);
        INFO("p = " << p << " seed " << seed << " flipped " << flipped);
        CHECK(orient_outward(m.V, F) == flipped);
        CHECK(F == m.F);  // a flip swaps columns 1 and 2: flipping back restores the rows exactly
      }
}

TEST_CASE("orient_outward turns an inside-out mesh outward", "[mesh][orientation]") {
  auto t = fx::torus(16, 8, 2, 0.5);
  FaceMatrix F = fx::flipped_all(t.F);
  CHECK(enclosed_volume(t.V, F) < 0);
  CHECK(orient_outward(t.V, F) == t.F.rows());
  CHECK(enclosed_volume(t.V, F) > 0);
  CHECK(F == t.F);
}

TEST_CASE("orient_outward treats each component on its own", "[mesh][orientation]") {
  // The cube as it is, the octahedron (shifted away) inside out, plus one flipped cube face.
  const auto c = fx::unit_cube();
  const auto o = fx::translated(fx::octahedron(), Eigen::RowVector3d(5, 0, 0));
  VertexMatrix V(14, 3);
  V << c.V, o.V;
  FaceMatrix F(20, 3), expected(20, 3);
  expected << c.F, (o.F.array() + 8).matrix();
  F = expected;
  for (int f = 12; f < 20; ++f) fx::flip_face(F, f);
  fx::flip_face(F, 3);
  CHECK(orient_outward(V, F) == 9);
  CHECK(F == expected);
}

TEST_CASE("orient_outward on open meshes keeps the majority orientation", "[mesh][orientation]") {
  // A UV sphere without its south cap: open, so no inside; the faces that were flipped (fewer
  // than half) are turned back.
  const auto s = fx::uv_sphere(16, 8, 1);
  const FaceMatrix open = s.F.topRows(s.F.rows() - 16);
  FaceMatrix F = open;
  const long flipped = flip_randomly(F, 0.2, 42);
  REQUIRE(flipped > 0);
  CHECK(orient_outward(s.V, F) == flipped);
  CHECK(F == open);
  // and the same mesh with most faces flipped ends up consistent, with the minority flipped
  F = open;
  const long most = flip_randomly(F, 0.8, 43);
  CHECK(orient_outward(s.V, F) == static_cast<long>(open.rows()) - most);
  CHECK(F == fx::flipped_all(open));
  CHECK(manifold_report(F, static_cast<int>(s.V.rows())).consistently_oriented());
}

TEST_CASE("orient_outward throws on a Moebius strip and on non-manifold input, leaving F alone", "[mesh][orientation]") {
  const auto strip = fx::moebius_strip(15, 2, 0.5);
  FaceMatrix F = strip.F;
  CHECK_THROWS_AS(orient_outward(strip.V, F), cmp::ComputationError);
  CHECK(F == strip.F);
  flip_randomly(F, 0.5, 3);
  const FaceMatrix shuffled = F;
  CHECK_THROWS_WITH(orient_outward(strip.V, F), Catch::Contains("not orientable"));
  CHECK(F == shuffled);

  const auto fan = fx::three_triangles_on_one_edge();
  FaceMatrix G = fan.F;
  CHECK_THROWS_WITH(orient_outward(fan.V, G), Catch::Contains("edge (0, 1) is in 3 faces"));
  CHECK(G == fan.F);

  auto c = fx::unit_cube();
  c.F(4, 2) = c.F(4, 0);  // degenerate
  CHECK_THROWS_AS(orient_outward(c.V, c.F), cmp::ComputationError);
  c.F(4, 2) = 8;
  CHECK_THROWS_AS(orient_outward(c.V, c.F), std::out_of_range);
}
