#include "elasticity/von_karman_plate.hpp"

#include "elasticity/clamped_plate.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace cmp::elasticity;

TEST_CASE("von Karman clamped plate: linear at small load, B.88 within a few percent, Hencky's membrane at large load",
          "[elasticity][plate]") {
  const std::vector<double> stars{0.01, 1, 10, 100, 1000, 3000, 1e4};
  for (double nu : {0.0, 0.3}) {
    INFO("nu = " << nu);
    const auto w = von_karman_max_deflection(nu, stars);
    REQUIRE(w.size() == stars.size());
    // Small load: B.87.
    CHECK(w[0] == Approx(12 * (1 - nu * nu) / 64 * stars[0]).epsilon(1e-5));
    // The approximate B.88 stays within 2 % (nu = 0) and 3.5 % (nu = 0.3).
    for (std::size_t i = 0; i < stars.size(); ++i)
      CHECK(std::abs(w[i] / large_deflection_max_deflection(nu, stars[i]) - 1) < (nu == 0 ? 0.02 : 0.035));
    for (std::size_t i = 1; i < stars.size(); ++i) CHECK(w[i] > w[i - 1]);
  }
  // Hencky's membrane solution at nu = 0.3, w/R0 = 0.662 (q R0/(E t))^(1/3), i.e. w/t = 0.662 P*^(1/3),
  // approached from below as the edge's bending layer thins.
  const auto w = von_karman_max_deflection(0.3, {1000, 3000, 1e4});
  double last = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double ratio = w[i] / (0.662 * std::cbrt(std::vector<double>{1000, 3000, 1e4}[i]));
    CHECK(ratio < 1.0);
    CHECK(ratio > last);
    last = ratio;
  }
  CHECK(last == Approx(0.98).margin(0.01));
  CHECK_THROWS_AS(von_karman_max_deflection(0.3, {10, 5}), std::domain_error);
}
