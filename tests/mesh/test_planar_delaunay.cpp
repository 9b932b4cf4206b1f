#include "mesh/planar_delaunay.hpp"

#include "core/random.hpp"
#include "flat_mesh_checks.hpp"
#include "mesh/face_areas.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::mesh;

TEST_CASE("planar Delaunay: random points, empty circumcircles, convex hull covered", "[mesh][delaunay]") {
  cmp::Random rng(7, 0);
  const int n = 300;
  TriMesh m;
  m.V.resize(n + 4, 3);
  for (int i = 0; i < n; ++i) m.V.row(i) << 0.01 + 0.98 * rng.uniform(), 0.01 + 0.98 * rng.uniform(), 0.0;
  m.V.row(n) << 0, 0, 0;
  m.V.row(n + 1) << 1, 0, 0;
  m.V.row(n + 2) << 1, 1, 0;
  m.V.row(n + 3) << 0, 1, 0;
  m.F = planar_delaunay(m.V);
  fixtures::check_flat_sheet(m, 0.0);
  CHECK(m.F.rows() == 2 * (n + 4) - 2 - 4);  // 2V - 2 - h with a hull of h = 4 points
  CHECK(total_area(m.V, m.F) == Approx(1.0).epsilon(1e-12));
  // No point strictly inside any circumcircle.
  int violations = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector2d a = m.V.row(m.F(f, 0)).head<2>(), b = m.V.row(m.F(f, 1)).head<2>(),
                          c = m.V.row(m.F(f, 2)).head<2>();
    const Eigen::Vector2d B = b - a, C = c - a;
    const double D = 2 * (B.x() * C.y() - B.y() * C.x());
    const Eigen::Vector2d u((C.y() * B.squaredNorm() - B.y() * C.squaredNorm()) / D,
                            (B.x() * C.squaredNorm() - C.x() * B.squaredNorm()) / D);
    for (Eigen::Index v = 0; v < m.V.rows(); ++v)
      if ((m.V.row(v).head<2>().transpose() - a - u).squaredNorm() < u.squaredNorm() * (1 - 1e-9)) ++violations;
  }
  CHECK(violations == 0);
  CHECK_THROWS_AS(planar_delaunay(m.V.topRows(2)), std::invalid_argument);
}
