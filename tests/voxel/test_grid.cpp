#include "voxel/grid.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

using namespace cmp::voxel;

TEST_CASE("make_grid rounds L / delta and reports the actual spacing", "[voxel][grid]") {
  const auto g = make_grid(Eigen::Vector3d(1.0, 2.0, 0.55), 0.1);
  CHECK(g.dims == std::array<int, 3>{10, 20, 6});  // 5.5 rounds to 6 (half away from zero)
  CHECK(g.spacing[0] == Approx(0.1));
  CHECK(g.spacing[2] == Approx(0.55 / 6));
  CHECK(g.size() == 1200);
  CHECK(g.index(1, 2, 3) == 1 + 10 * (2 + 20 * 3));
  const auto h = make_grid(Eigen::Vector3d(3.0, 3.0, 3.0), 0.29);  // 10.34 -> 10
  CHECK(h.dims[0] == 10);
  CHECK(h.spacing[0] == Approx(0.3));
  CHECK(make_grid(Eigen::Vector3d(1.0, 1.0, 1.0), 1.0).dims == std::array<int, 3>{1, 1, 1});
}

TEST_CASE("make_grid rejects a bad delta", "[voxel][grid]") {
  const Eigen::Vector3d box(1.0, 2.0, 3.0);
  CHECK_THROWS_AS(make_grid(box, 0), cmp::UsageError);
  CHECK_THROWS_AS(make_grid(box, -0.1), cmp::UsageError);
  CHECK_THROWS_AS(make_grid(box, std::nan("")), cmp::UsageError);
  CHECK_THROWS_WITH(make_grid(box, 1.5), Catch::Contains("larger than the box"));
  CHECK_THROWS_WITH(make_grid(box, 1e-4), Catch::Contains("2^31"));
}
