#include "mesh/rectangle_mesh.hpp"

#include "flat_mesh_checks.hpp"
#include "mesh/face_areas.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace cmp::mesh;

TEST_CASE("rectangular sheets of the Poisson benchmark: counts, edges, orientation, area, quality", "[mesh][rectangle]") {
  // Fig. B.4B: L = 2.28, N ~ 2200.
  for (auto [W, H, N] : {std::tuple{2.28, 2.28, 2200L}, std::tuple{2.0, 1.0, 300L}, std::tuple{1.0, 1.0, 9L}}) {
    INFO("W = " << W << ", H = " << H << ", N = " << N);
    const RectangleMesh r = rectangle_mesh(W, H, N);
    CHECK(std::abs(r.mesh.V.rows() - N) <= 0.05 * N + 3);
    const auto boundary = fixtures::check_flat_sheet(r.mesh, 25.0);
    std::set<int> edges(r.left.begin(), r.left.end());
    edges.insert(r.right.begin(), r.right.end());
    edges.insert(r.bottom.begin(), r.bottom.end());
    edges.insert(r.top.begin(), r.top.end());
    CHECK(boundary == edges);
    for (int v : r.left) CHECK(r.mesh.V(v, 0) == 0.0);
    for (int v : r.right) CHECK(r.mesh.V(v, 0) == W);
    for (int v : r.bottom) CHECK(r.mesh.V(v, 1) == 0.0);
    for (int v : r.top) CHECK(r.mesh.V(v, 1) == H);
    for (std::size_t i = 1; i < r.left.size(); ++i) CHECK(r.mesh.V(r.left[i], 1) > r.mesh.V(r.left[i - 1], 1));
    for (std::size_t i = 1; i < r.bottom.size(); ++i) CHECK(r.mesh.V(r.bottom[i], 0) > r.mesh.V(r.bottom[i - 1], 0));
    CHECK(total_area(r.mesh.V, r.mesh.F) == Approx(W * H).epsilon(1e-12));
  }
  CHECK(rectangle_mesh(2.28, 2.28, 2200).spacing == Approx(0.053).margin(0.003));
  CHECK_THROWS_AS(rectangle_mesh(0.0, 1.0, 100), std::invalid_argument);
}
