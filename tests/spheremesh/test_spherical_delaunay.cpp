#include "mesh/enclosed_volume.hpp"
#include "mesh/manifold.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"
#include "spheremesh/subdivision.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

using namespace cmp;

namespace {
// Delaunay on the sphere = convex hull: every other point lies on the inner side of each
// face's plane (the empty-circle property, as circles on a sphere are planes).
long hull_violations(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F) {
  long bad = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      if (n.dot(Eigen::Vector3d(V.row(i)) - a) > 1e-12) ++bad;
  }
  return bad;
}
}  // namespace

TEST_CASE("Spherical Delaunay of random points is a closed, outward, Delaunay mesh", "[delaunay]") {
  for (int n : {4, 5, 17, 100, 1000}) {
    // Random points would often leave a hemisphere empty for small N (P = 7/8 for N = 4):
    // a short anneal spreads them over the sphere, as rndmesh does.
    spheremesh::AnnealingParameters p;
    p.points = n, p.radius = 1.7, p.seed = 42 + n, p.anneals = 5, p.sweeps_per_anneal = 5, p.t_max = 1;
    const auto points = spheremesh::anneal_on_sphere(p).points;
    const auto faces = spheremesh::spherical_delaunay(points);
    INFO("N = " << n);
    CHECK(faces.rows() == 2 * n - 4);
    const auto report = mesh::manifold_report(faces, n);
    CHECK(report.closed_manifold());
    CHECK(report.consistently_oriented());
    CHECK(report.euler_characteristic == 2);
    CHECK(report.unused_vertices == 0);
    CHECK(mesh::enclosed_volume(points, faces) > 0);
    if (n <= 100) CHECK(hull_violations(points, faces) == 0);
  }
}

TEST_CASE("Spherical Delaunay retriangulates an icosahedral mesh's vertices", "[delaunay]") {
  const auto m = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, 3, 1.0);
  const auto faces = spheremesh::spherical_delaunay(m.V);
  CHECK(faces.rows() == m.F.rows());
  CHECK(mesh::enclosed_volume(m.V, faces) == Approx(mesh::enclosed_volume(m.V, m.F)).epsilon(1e-12));
}

TEST_CASE("Spherical Delaunay refuses degenerate input", "[delaunay]") {
  mesh::VertexMatrix hemisphere(5, 3);  // no point below the equator: no closed triangulation
  hemisphere << 1, 0, 0.1, 0, 1, 0.1, -1, 0, 0.1, 0, -1, 0.1, 0, 0, 1;
  for (Eigen::Index i = 0; i < 5; ++i) hemisphere.row(i).normalize();
  CHECK_THROWS_AS(spheremesh::spherical_delaunay(hemisphere), ComputationError);
  mesh::VertexMatrix three(3, 3);
  three << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  CHECK_THROWS_AS(spheremesh::spherical_delaunay(three), ComputationError);
  mesh::VertexMatrix duplicate(5, 3);
  duplicate << 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 1, 0, 0;
  CHECK_THROWS_AS(spheremesh::spherical_delaunay(duplicate), ComputationError);
  mesh::VertexMatrix circle(6, 3);  // all on the equator
  for (int i = 0; i < 6; ++i) circle.row(i) << std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0;
  CHECK_THROWS_AS(spheremesh::spherical_delaunay(circle), ComputationError);
}
