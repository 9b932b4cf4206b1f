// The winding-number inside test against shapes whose inside is known.
#include "mesh/point_in_mesh.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

TEST_CASE("winding number: 1 inside and 0 outside the unit cube, also a hair from a face", "[mesh][inside]") {
  const auto cube = fx::unit_cube();
  CHECK(winding_number(cube.V, cube.F, {0.5, 0.5, 0.5}) == Approx(1.0).margin(1e-12));
  CHECK(winding_number(cube.V, cube.F, {0.3, 0.9, 0.1}) == Approx(1.0).margin(1e-12));
  CHECK(winding_number(cube.V, cube.F, {1.5, 0.5, 0.5}) == Approx(0.0).margin(1e-12));
  CHECK(winding_number(cube.V, cube.F, {-3, 7, 2}) == Approx(0.0).margin(1e-12));
  // Close to a face and to an edge, on both sides.
  CHECK(inside_closed_mesh(cube.V, cube.F, {0.5, 0.5, 1 - 1e-9}));
  CHECK(!inside_closed_mesh(cube.V, cube.F, {0.5, 0.5, 1 + 1e-9}));
  CHECK(inside_closed_mesh(cube.V, cube.F, {1 - 1e-9, 0.5, 1 - 1e-9}));
  CHECK(!inside_closed_mesh(cube.V, cube.F, {1 + 1e-9, 0.5, 1 - 1e-9}));
  // Inward faces turn the sign.
  auto flipped = cube;
  for (Eigen::Index f = 0; f < flipped.F.rows(); ++f) fx::flip_face(flipped.F, f);
  CHECK(winding_number(flipped.V, flipped.F, {0.5, 0.5, 0.5}) == Approx(-1.0).margin(1e-12));
}

TEST_CASE("winding number: a torus's hole is outside, its tube inside", "[mesh][inside]") {
  const auto t = fx::torus(48, 24, 2.0, 0.5);
  CHECK(!inside_closed_mesh(t.V, t.F, {0, 0, 0}));     // the hole
  CHECK(inside_closed_mesh(t.V, t.F, {2.0, 0, 0}));    // the tube's centre line
  CHECK(inside_closed_mesh(t.V, t.F, {0, -2.3, 0.1}));
  CHECK(!inside_closed_mesh(t.V, t.F, {0, -2.6, 0}));  // past the tube
  CHECK(!inside_closed_mesh(t.V, t.F, {2.0, 0, 0.6}));
}
