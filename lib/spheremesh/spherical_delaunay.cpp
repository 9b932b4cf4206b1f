// gmpxx.h declares a global function template `cmp`, which clashes with this toolkit's
// namespace; CGAL needs only GMP's C interface, so keep gmpxx out of this translation unit.
#undef CGAL_USE_GMPXX
#include "spheremesh/spherical_delaunay.hpp"

#include "core/errors.hpp"

#include <CGAL/Delaunay_triangulation_on_sphere_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_on_sphere_traits_3.h>

#include <fmt/format.h>

#include <unordered_map>

namespace cmp::spheremesh {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Projection_on_sphere_traits_3<Kernel>;
using Triangulation = CGAL::Delaunay_triangulation_on_sphere_2<Traits>;

// Exact key of a point's coordinates, to map CGAL's vertices back to input indices.
struct PointKey {
  double x, y, z;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    const std::hash<double> h;
    return h(k.x) ^ (h(k.y) * 0x9e3779b97f4a7c15ULL) ^ (h(k.z) * 0xbf58476d1ce4e5b9ULL);
  }
};
}  // namespace

mesh::FaceMatrix spherical_delaunay(const mesh::VertexMatrix& points) {
  const Eigen::Index n = points.rows();
  if (n < 4) throw ComputationError(fmt::format("spherical Delaunay needs at least 4 points, got {}", n));
  std::unordered_map<PointKey, int, PointKeyHash> index;
  index.reserve(static_cast<std::size_t>(n));
  std::vector<Traits::Point_on_sphere_2> sites;
  sites.reserve(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const PointKey key{points(i, 0), points(i, 1), points(i, 2)};
    if (!index.emplace(key, static_cast<int>(i)).second)
      throw ComputationError(fmt::format("points {} and {} coincide", index[key], i));
    sites.emplace_back(Kernel::Point_3(key.x, key.y, key.z));
  }

  Traits traits(Kernel::Point_3(0, 0, 0), 1.0);
  Triangulation dt(traits);
  dt.insert(sites.begin(), sites.end());  // spatially sorted insertion
  if (dt.dimension() != 2 || dt.number_of_ghost_faces() != 0)
    throw ComputationError("the points do not span the sphere (all on one hemisphere or great circle)");
  if (static_cast<Eigen::Index>(dt.number_of_vertices()) != n)
    throw ComputationError(fmt::format("{} of {} points were too close to another to be triangulated",
                                       n - static_cast<Eigen::Index>(dt.number_of_vertices()), n));

  mesh::FaceMatrix faces(static_cast<Eigen::Index>(dt.number_of_solid_faces()), 3);
  Eigen::Index f = 0;
  for (auto face = dt.solid_faces_begin(); face != dt.solid_faces_end(); ++face, ++f)
    for (int k = 0; k < 3; ++k) {
      const auto& p = face->vertex(k)->point();
      faces(f, k) = index.at(PointKey{p.x(), p.y(), p.z()});
    }
  // CGAL orients faces counter-clockwise seen from outside; check one and flip all if not.
  const Eigen::Vector3d a = points.row(faces(0, 0)), b = points.row(faces(0, 1)), c = points.row(faces(0, 2));
  if ((b - a).cross(c - a).dot(a + b + c) < 0) faces.col(1).swap(faces.col(2));
  return faces;
}

}  // namespace cmp::spheremesh
