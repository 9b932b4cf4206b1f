#include "flowrun/pore_cluster.hpp"
#include "flowrun/refine.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

using namespace cmp::flowrun;

namespace {
std::size_t at(std::array<int, 3> d, int x, int y, int z) { return x + d[0] * (y + static_cast<std::size_t>(d[1]) * z); }
}  // namespace

TEST_CASE("percolating_cluster keeps the channels that span the axis and counts the pockets", "[flowrun][cluster]") {
  const std::array<int, 3> d{6, 5, 5};
  std::vector<std::uint8_t> m(d[0] * d[1] * d[2], 0);
  for (int x = 0; x < 6; ++x) m[at(d, x, 1, 1)] = 1;        // a straight channel along x
  m[at(d, 2, 3, 2)] = m[at(d, 3, 3, 2)] = 1;                  // a pocket
  for (int x = 0; x < 4; ++x) m[at(d, x, 3, 0)] = 1;          // a dead end from the inlet
  // A channel along x that crosses the periodic y boundary: spans only through it.
  for (int x = 0; x < 3; ++x) m[at(d, x, 0, 3)] = 1;
  for (int x = 2; x < 6; ++x) m[at(d, x, 4, 3)] = 1;
  const auto c = percolating_cluster(m, d, 0);
  CHECK(c.components == 4);
  CHECK(c.spanning == 2);
  CHECK(c.dropped_components == 2);
  CHECK(c.fluid_voxels == 6 + 2 + 4 + 3 + 4);
  CHECK(c.cluster_voxels == 6 + 3 + 4);
  CHECK(c.dropped_voxels == 6);
  CHECK(c.fluid[at(d, 0, 1, 1)] == 1);
  CHECK(c.fluid[at(d, 2, 3, 2)] == 0);
  CHECK(c.fluid[at(d, 0, 3, 0)] == 0);
  CHECK(c.fluid[at(d, 5, 4, 3)] == 1);
  // Along y nothing spans.
  CHECK(percolating_cluster(m, d, 1).spanning == 0);
  // The same for any thread count.
  for (int t : {1, 2}) {
    omp_set_num_threads(t);
    CHECK(percolating_cluster(m, d, 0).fluid == c.fluid);
  }
}

TEST_CASE("refine_mask turns each voxel into M^3 nodes", "[flowrun][refine]") {
  const std::array<int, 3> d{2, 1, 3};
  const std::vector<std::uint8_t> m{1, 0, 0, 1, 1, 1};
  CHECK(refine_mask(m, d, 1) == m);
  const auto r = refine_mask(m, d, 3);
  REQUIRE(r.size() == 6u * 27u);
  const std::array<int, 3> n{6, 3, 9};
  for (int z = 0; z < 9; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 6; ++x) REQUIRE(r[at(n, x, y, z)] == m[at(d, x / 3, y / 3, z / 3)]);
  CHECK_THROWS_AS(refine_mask(m, d, 0), std::invalid_argument);
  CHECK_THROWS_AS(refine_mask(m, {2, 2, 2}, 1), std::invalid_argument);
}
