// The ray-crossing inside test against the winding number it stands in for, on shapes where
// the ray meets the surface many times, edge-on faces and points on shadow edges and corners.
#include "mesh/inside_query.hpp"
#include "mesh/point_in_mesh.hpp"

#include "mesh_fixtures.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace cmp::mesh;
namespace fx = cmp::mesh::fixtures;

namespace {

// A uv sphere with a deep dimple at the top (the surface folds below the equator's height
// there, so a vertical ray meets it four times) and a little radial noise, turned about an
// oblique axis so that no face is axis-aligned.
TriMesh dimpled_sphere() {
  TriMesh m = fx::uv_sphere(40, 20, 1.0);
  cmp::Random rng(7);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    const Eigen::Vector3d p = m.V.row(v).transpose();
    const double dent = 1.3 * std::exp(-(p - Eigen::Vector3d(0, 0, 1)).squaredNorm() / 0.5);
    m.V.row(v) = (p * (1.0 - 0.02 * rng.uniform()) - Eigen::Vector3d(0, 0, dent)).transpose();
  }
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized()).toRotationMatrix();
  m.V = (m.V * turn.transpose()).eval();
  return m;
}

// Every point answered as the winding number answers it; returns how many are inside.
long agree_everywhere(const TriMesh& m, const std::vector<Eigen::Vector3d>& points, const std::string& what,
                      long* undecided = nullptr) {
  const InsideQuery query(m.V.data(), m.F, 0, m.F.rows());
  long inside = 0, mismatches = 0;
  for (const auto& p : points) {
    const bool expected = winding_number(m.V, m.F, p) > 0.5;
    if (query.inside(p) != expected) {
      ++mismatches;
      UNSCOPED_INFO(what << ": " << p.transpose() << " winding " << winding_number(m.V, m.F, p));
    }
    inside += expected;
  }
  CHECK(mismatches == 0);
  if (undecided) *undecided = query.undecided();
  return inside;
}

// Random points in the mesh's bounding box (10 % wider), and each vertex moved by small
// random offsets (both sides of the surface, 1e-3 to 1e-9 of the size).
std::vector<Eigen::Vector3d> probes(const TriMesh& m, std::uint64_t seed) {
  cmp::Random rng(seed);
  const Eigen::Vector3d lo = m.V.colwise().minCoeff().transpose(), hi = m.V.colwise().maxCoeff().transpose();
  const Eigen::Vector3d pad = 0.1 * (hi - lo);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 20000; ++k) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p[a] = rng.uniform(lo[a] - pad[a], hi[a] + pad[a]);
    out.push_back(p);
  }
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    for (double scale : {1e-3, 1e-6, 1e-9}) {
      const Eigen::Vector3d p = m.V.row(v).transpose();
      out.push_back(p + scale * Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()));
      // Straight above or below the vertex: p's shadow on a shadow corner.
      out.push_back(p + Eigen::Vector3d(0, 0, rng.uniform(-1.0, 1.0)));
    }
  return out;
}

}  // namespace

TEST_CASE("inside query: the winding number's answer on a dimpled sphere and a torus, near and on the surface",
          "[mesh][inside]") {
  const TriMesh dimpled = dimpled_sphere();
  const auto on_dimpled = probes(dimpled, 1);
  const long in_dimpled = agree_everywhere(dimpled, on_dimpled, "dimpled sphere");
  CHECK(in_dimpled > 1000);
  CHECK(in_dimpled < static_cast<long>(on_dimpled.size()) - 1000);

  TriMesh torus = fx::torus(48, 24, 2.0, 0.5);
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 1, 0).normalized()).toRotationMatrix();
  torus.V = (torus.V * tilt.transpose()).eval();
  const auto on_torus = probes(torus, 2);
  const long in_torus = agree_everywhere(torus, on_torus, "torus");
  CHECK(in_torus > 500);
  CHECK(in_torus < static_cast<long>(on_torus.size()) - 1000);
}

TEST_CASE("inside query: axis-aligned faces and points on shadow edges go to the winding number", "[mesh][inside]") {
  // The unit cube's side faces cast no shadow; the diagonals of its top and bottom faces
  // run through (0.5, 0.5), and its corners through (0, 0), (1, 1) ...
  const TriMesh cube = fx::unit_cube();
  std::vector<Eigen::Vector3d> points;
  for (double x : {-0.5, 0.0, 0.25, 0.5, 1.0, 1.5})
    for (double y : {0.0, 0.25, 0.5, 0.75, 1.0})
      for (double z : {-1.0, 0.0, 1e-12, 0.5, 1.0 - 1e-9, 1.0, 2.0}) points.emplace_back(x, y, z);
  long undecided = 0;
  const long in_cube = agree_everywhere(cube, points, "cube", &undecided);
  CHECK(in_cube > 10);
  CHECK(undecided > 0);  // the fallback was taken (and agreed)
  // Off the shadow edges, the crossings decide alone.
  const InsideQuery query(cube.V.data(), cube.F, 0, cube.F.rows());
  CHECK(query.inside({0.3, 0.6, 0.5}));
  CHECK(!query.inside({0.3, 0.6, 1.5}));
  CHECK(!query.inside({0.3, 0.6, -0.5}));
  CHECK(query.undecided() == 0);
}

TEST_CASE("inside query: a subset of a larger mesh's faces, and an empty one", "[mesh][inside]") {
  // Two cubes in one mesh: the query over the second's faces sees only the second.
  TriMesh two;
  const TriMesh cube = fx::unit_cube();
  two.V.resize(16, 3);
  two.F.resize(24, 3);
  two.V << cube.V, cube.V.rowwise() + Eigen::RowVector3d(3, 0, 0);
  two.F << cube.F, cube.F.array() + 8;
  const InsideQuery second(two.V.data(), two.F, 12, 24);
  CHECK(second.inside({3.3, 0.6, 0.5}));
  CHECK(!second.inside({0.3, 0.6, 0.5}));
  const InsideQuery none(two.V.data(), two.F, 0, 0);
  CHECK(!none.inside({0.3, 0.6, 0.5}));
}
