// gmpxx.h declares a global function template `cmp`, which clashes with this toolkit's
// namespace; CGAL needs only GMP's C interface (as in spheremesh/spherical_delaunay.cpp).
#undef CGAL_USE_GMPXX
#include "shell/voronoi_faces.hpp"
#include "core/minimum_image.hpp"

#include "core/errors.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_3_Delaunay_triangulation_3.h>
#include <CGAL/Periodic_3_Delaunay_triangulation_traits_3.h>

#include <cmath>
#include <iterator>
#include <map>
#include <tuple>

namespace cmp::shell {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Periodic_3_Delaunay_triangulation_traits_3<Kernel>;
using Triangulation = CGAL::Periodic_3_Delaunay_triangulation_3<Traits>;
using Point = Triangulation::Point;


// Area of the planar polygon p (vertices in order around it).
double polygon_area(const std::vector<Point>& p) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const Eigen::Vector3d a(p[k].x() - p[0].x(), p[k].y() - p[0].y(), p[k].z() - p[0].z());
    const Eigen::Vector3d b(p[k + 1].x() - p[0].x(), p[k + 1].y() - p[0].y(), p[k + 1].z() - p[0].z());
    sum += a.cross(b);
  }
  return 0.5 * sum.norm();
}
}  // namespace

std::vector<int> periodic_voronoi_face_counts(const mesh::VertexMatrix& P, double side) {
  if (!(side > 0) || !std::isfinite(side)) throw UsageError("periodic Voronoi cells: the cube side must be positive");
  const Eigen::Index n = P.rows();
  std::vector<int> faces(static_cast<std::size_t>(n), 0);
  if (n == 0) return faces;
  Triangulation T(Triangulation::Iso_cuboid(0, 0, 0, side, side, side));
  std::map<std::tuple<double, double, double>, Eigen::Index> index;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Point p(wrap_into_period(P(i, 0), side), wrap_into_period(P(i, 1), side), wrap_into_period(P(i, 2), side));
    if (!index.emplace(std::make_tuple(p.x(), p.y(), p.z()), i).second)
      throw UsageError("periodic Voronoi cells: points " + std::to_string(index[{p.x(), p.y(), p.z()}]) + " and " +
                       std::to_string(i) + " are at the same place");
    T.insert(p);
  }
  const double tolerance = 1e-9 * std::pow(side * side * side / static_cast<double>(n), 2.0 / 3.0);
  std::vector<Triangulation::Edge> edges;
  std::vector<Point> polygon;
  // unique_vertices: one per input point, also on the 27-sheeted cover (few points), where
  // the star of that copy is the cell's star and every Delaunay edge out of it one facet.
  for (auto v = T.unique_vertices_begin(); v != T.unique_vertices_end(); ++v) {
    const auto& q = v->point();
    const auto it = index.find(std::make_tuple(q.x(), q.y(), q.z()));
    if (it == index.end()) throw ComputationError("periodic Voronoi cells: a vertex is not an input point");
    edges.clear();
    T.incident_edges(v, std::back_inserter(edges));
    int count = 0;
    for (const auto& e : edges) {
      polygon.clear();
      T.dual(e, std::back_inserter(polygon));
      if (polygon_area(polygon) > tolerance) ++count;
    }
    faces[static_cast<std::size_t>(it->second)] = count;
  }
  return faces;
}

}  // namespace cmp::shell
