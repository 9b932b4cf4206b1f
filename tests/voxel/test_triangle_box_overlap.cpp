#include "voxel/triangle_box_overlap.hpp"

#include "core/random.hpp"

#include <catch2/catch.hpp>

using namespace cmp::voxel;
using V3 = Eigen::Vector3d;

TEST_CASE("triangle_box_overlap on simple configurations", "[voxel][overlap]") {
  const V3 c(0, 0, 0), h(0.5, 0.5, 0.5);
  CHECK(triangle_box_overlap(V3(-2, -2, 0), V3(2, -2, 0), V3(0, 2, 0), c, h));     // cuts through
  CHECK(triangle_box_overlap(V3(0.1, 0.1, 0.1), V3(0.2, 0.1, 0.1), V3(0.1, 0.2, 0.1), c, h));  // inside
  CHECK(!triangle_box_overlap(V3(-2, -2, 0.6), V3(2, -2, 0.6), V3(0, 2, 0.6), c, h));  // parallel above
  CHECK(triangle_box_overlap(V3(-2, -2, 0.5), V3(2, -2, 0.5), V3(0, 2, 0.5), c, h));   // touching a face
  // Bounding boxes overlap but the plane misses the corner (1,1,1)/2: x + y + z = 1.6.
  CHECK(!triangle_box_overlap(V3(1.6, 0, 0), V3(0, 1.6, 0), V3(0, 0, 1.6), c, h));
  CHECK(triangle_box_overlap(V3(1.4, 0, 0), V3(0, 1.4, 0), V3(0, 0, 1.4), c, h));
  // The plane z = 0 cuts the box, the triangle lies beside its corner (an edge-cross axis).
  CHECK(!triangle_box_overlap(V3(0.8, 1.0, 0), V3(1.0, 0.8, 0), V3(5, 5, 0), c, h));  // beside the corner in 2D
  // degenerate: a segment through the box, a point outside
  CHECK(triangle_box_overlap(V3(-1, -1, -1), V3(1, 1, 1), V3(1, 1, 1), c, h));
  CHECK(!triangle_box_overlap(V3(0.6, 0, 0), V3(0.6, 0, 0), V3(0.6, 0, 0), c, h));
}

TEST_CASE("triangle_box_overlap agrees with dense sampling", "[voxel][overlap]") {
  // A sampled point of the triangle inside the box proves overlap; the exact test must say yes.
  // And when it says no, no sample may lie inside.
  cmp::Random r(3);
  const V3 c(0.5, 0.5, 0.5), h(0.5, 0.5, 0.5);
  int hits = 0, misses = 0;
  for (int t = 0; t < 3000; ++t) {
    V3 p[3];
    for (auto& q : p) q = V3(r.uniform(-1, 2), r.uniform(-1, 2), r.uniform(-1, 2));
    bool sampled = false;
    for (int i = 0; i <= 40 && !sampled; ++i)
      for (int j = 0; i + j <= 40 && !sampled; ++j) {
        const V3 x = p[0] + (p[1] - p[0]) * (i / 40.0) + (p[2] - p[0]) * (j / 40.0);
        sampled = ((x - c).array().abs() <= h.array()).all();
      }
    const bool exact = triangle_box_overlap(p[0], p[1], p[2], c, h);
    if (sampled) REQUIRE(exact);
    exact ? ++hits : ++misses;
  }
  CHECK(hits > 300);
  CHECK(misses > 300);
}
