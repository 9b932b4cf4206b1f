#include "flowrun/sphere_walls.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::flowrun;

TEST_CASE("SphereWalls marks node centres inside spheres, through periodic images", "[flowrun][walls]") {
  Eigen::MatrixX3d c(1, 3);
  c << 0.1, 0.5, 0.5;  // near the x = 0 face: its image covers nodes near x = 1
  Eigen::VectorXd r(1);
  r << 0.3;
  const SphereWalls w(Eigen::Vector3d(1, 1, 1), {true, true, true}, c, r, {10, 10, 10});
  const auto fluid = w.fluid_mask();
  long solid = 0;
  for (int z = 0; z < 10; ++z)
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x) {
        double dx = (x + 0.5) * 0.1 - 0.1;
        dx -= std::nearbyint(dx);
        const double dy = (y + 0.5) * 0.1 - 0.5, dz = (z + 0.5) * 0.1 - 0.5;
        const bool inside = dx * dx + dy * dy + dz * dz <= 0.09;
        REQUIRE(fluid[x + 10 * (y + 10 * z)] == (inside ? 0 : 1));
        solid += inside;
      }
  CHECK(solid > 0);
  CHECK(fluid[9 + 10 * (5 + 10 * 5)] == 0);  // x = 0.95 wraps to 0.05 from the centre
  // Not periodic in x: the image does not reach x = 0.95.
  const SphereWalls open(Eigen::Vector3d(1, 1, 1), {false, true, true}, c, r, {10, 10, 10});
  CHECK(open.fluid_mask()[9 + 10 * (5 + 10 * 5)] == 1);
}

TEST_CASE("SphereWalls::wall_fraction is where the link enters the sphere", "[flowrun][walls]") {
  Eigen::MatrixX3d c(1, 3);
  c << 0.5, 0.5, 0.5;
  Eigen::VectorXd r(1);
  r << 0.23;
  const SphereWalls w(Eigen::Vector3d(1, 1, 1), {true, true, true}, c, r, {10, 10, 10});
  // Node (2, 4, 4)... sits at (0.25, 0.45, 0.45); along +x the surface at x = 0.5 - sqrt(r^2 - 2 * 0.05^2).
  const double surface = 0.5 - std::sqrt(0.23 * 0.23 - 2 * 0.05 * 0.05);
  CHECK(w.wall_fraction(2, 4, 4, {1, 0, 0}) == Approx((surface - 0.25) / 0.1));
  // Away from the sphere: no entry, the half-way default.
  CHECK(w.wall_fraction(2, 4, 4, {-1, 0, 0}) == 0.5);
  // A diagonal link: solve |p + t e - c| = r directly.
  const Eigen::Vector3d p(0.25, 0.45, 0.35), e(0.1, 0, 0.1), d = p - Eigen::Vector3d(0.5, 0.5, 0.5);
  const double a = e.squaredNorm(), b = d.dot(e), cc = d.squaredNorm() - 0.23 * 0.23;
  const double t = (-b - std::sqrt(b * b - a * cc)) / a;
  if (t <= 1) CHECK(w.wall_fraction(2, 4, 3, {1, 0, 1}) == Approx(t));
  // Every fluid node next to a solid node gets a fraction in (0, 1].
  const auto fluid = w.fluid_mask();
  int links = 0;
  for (int z = 1; z < 9; ++z)
    for (int y = 1; y < 9; ++y)
      for (int x = 1; x < 9; ++x)
        for (int cx = -1; cx <= 1; ++cx)
          for (int cy = -1; cy <= 1; ++cy)
            for (int cz = -1; cz <= 1; ++cz) {
              if (std::abs(cx) + std::abs(cy) + std::abs(cz) == 0 || std::abs(cx) + std::abs(cy) + std::abs(cz) == 3) continue;
              if (!fluid[x + 10 * (y + 10 * z)] || fluid[(x + cx) + 10 * ((y + cy) + 10 * (z + cz))]) continue;
              const double q = w.wall_fraction(x, y, z, {cx, cy, cz});
              REQUIRE(q > 0);
              REQUIRE(q <= 1);
              REQUIRE(q != 0.5);  // every cut link here meets the sphere
              ++links;
            }
  CHECK(links > 50);
}
