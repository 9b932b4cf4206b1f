#include "mesh/disc_mesh.hpp"

#include "flat_mesh_checks.hpp"
#include "mesh/face_areas.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace cmp::mesh;

TEST_CASE("disc meshes of the plate benchmarks: counts, rim, orientation, area, quality", "[mesh][disc]") {
  // Figs. B.5-B.6 (N ~ 1200, a ~ 0.3 on R0 = 2.25 in the thesis's words) and Fig. B.7 (N ~ 1000).
  for (auto [R, N] : {std::pair{2.25, 1200L}, std::pair{2.14, 1000L}, std::pair{1.0, 60L}}) {
    INFO("R = " << R << ", N = " << N);
    const DiscMesh d = disc_mesh(R, N);
    CHECK(std::abs(d.mesh.V.rows() - N) <= 0.03 * N + 3);
    const auto boundary = fixtures::check_flat_sheet(d.mesh, 25.0);
    // The boundary is exactly the rim, in angular order, on the circle.
    CHECK(boundary == std::set<int>(d.rim.begin(), d.rim.end()));
    double previous = -M_PI - 1;
    for (int v : d.rim) {
      CHECK(std::hypot(d.mesh.V(v, 0), d.mesh.V(v, 1)) == Approx(R).epsilon(1e-14));
      const double angle = std::atan2(d.mesh.V(v, 1), d.mesh.V(v, 0));
      CHECK(angle != previous);
      previous = angle;
    }
    for (Eigen::Index v = 0; v < d.mesh.V.rows(); ++v) CHECK(d.mesh.V.row(v).norm() <= R * (1 + 1e-14));
    // The area of the inscribed polygon of the rim.
    const double m = static_cast<double>(d.rim.size());
    CHECK(total_area(d.mesh.V, d.mesh.F) == Approx(0.5 * m * R * R * std::sin(2 * M_PI / m)).epsilon(1e-12));
    CHECK(d.mesh.V.row(d.centre).norm() == 0.0);
    // Rim spacing close to the lattice spacing.
    CHECK(2 * M_PI * R / m == Approx(d.spacing).epsilon(0.1));
  }
  CHECK(disc_mesh(2.25, 1200).spacing == Approx(0.12).margin(0.01));
  CHECK_THROWS_AS(disc_mesh(-1.0, 100), std::invalid_argument);
  CHECK_THROWS_AS(disc_mesh(1.0, 5), std::invalid_argument);
}
