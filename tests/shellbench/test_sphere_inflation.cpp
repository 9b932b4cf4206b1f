// Benchmark B.5.1 at test size: the SVK membrane follows the corrected large-strain SVK sphere
// relation up to dP/E = 1e-2; spring meshes agree only at small strain.
#include "shellbench/sphere_inflation.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::shell;
using namespace cmp::shellbench;

TEST_CASE("an inflated SVK sphere follows the corrected large-strain relation, springs only at small strain",
          "[shell][physics][sphere]") {
  SphereInflationCase c;
  c.level = 4;  // 642 vertices, the thesis's mesh
  c.loads = {1e-4, 1e-3, 1e-2};
  c.models = {"svk", "springs-kot", "springs-van-gelder"};
  const auto rows = sphere_inflation(c);
  REQUIRE(rows.size() == 9);
  for (const auto& r : rows) {
    INFO(r.model << " dP/E=" << r.load << " eps=" << r.strain << " corrected=" << r.strain_corrected
                 << " printed=" << r.strain_printed << " iterations=" << r.relax.iterations);
    CHECK(r.relax.converged());
    CHECK(r.relax.residual <= c.relative_tolerance);
    const double rel = std::abs(r.strain / r.strain_corrected - 1);
    // Measured (642 vertices): SVK within 0.33-0.40 % at every load (the printed B.82 is 16 %
    // off at 1e-2); Kot springs 3.2 % at 1e-4, 18 % at 1e-2.
    if (r.model == "svk") CHECK(rel < 0.006);
    if (r.model == "svk" && r.load >= 1e-2) CHECK(std::abs(r.strain / r.strain_printed - 1) > 0.1);
    if (r.model != "svk" && r.load <= 1e-4) CHECK(rel < 0.05);
  }
  // Springs: the error grows with the strain (by more than 10 points from 1e-4 to 1e-2).
  for (std::size_t k = 3; k < rows.size(); k += 3) {
    INFO(rows[k].model);
    CHECK(std::abs(rows[k + 2].strain / rows[k + 2].strain_corrected - 1) -
              std::abs(rows[k].strain / rows[k].strain_corrected - 1) > 0.1);
  }
}
