// gmpxx.h declares a global function template `cmp`, which clashes with this toolkit's
// namespace; CGAL needs only GMP's C interface, so keep gmpxx out of this translation unit.
#undef CGAL_USE_GMPXX
#include "spheremesh/spherical_delaunay.hpp"

#include "core/errors.hpp"

#include <CGAL/Delaunay_triangulation_on_sphere_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_on_sphere_traits_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <fmt/format.h>

#include <numeric>

namespace cmp::spheremesh {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Projection_on_sphere_traits_3<Kernel>;

// A vertex that remembers which input point it is, so faces map back without a lookup.
template <class Gt, class Vb = CGAL::Triangulation_on_sphere_vertex_base_2<Gt>>
class IndexedVertex : public Vb {
 public:
  template <typename TDS2>
  struct Rebind_TDS {
    using Vb2 = typename Vb::template Rebind_TDS<TDS2>::Other;
    using Other = IndexedVertex<Gt, Vb2>;
  };
  using Vb::Vb;
  int index = -1;
};

using Tds = CGAL::Triangulation_data_structure_2<IndexedVertex<Traits>, CGAL::Triangulation_on_sphere_face_base_2<Traits>>;
using Triangulation = CGAL::Delaunay_triangulation_on_sphere_2<Traits, Tds>;
}  // namespace

mesh::FaceMatrix spherical_delaunay(const mesh::VertexMatrix& points) {
  const Eigen::Index n = points.rows();
  if (n < 4) throw ComputationError(fmt::format("spherical Delaunay needs at least 4 points, got {}", n));
  std::vector<Kernel::Point_3> sites;
  sites.reserve(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) sites.emplace_back(points(i, 0), points(i, 1), points(i, 2));

  // Insert along a Hilbert curve, each point located from the last one's face: near-linear.
  std::vector<std::size_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  using SortTraits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(sites)));

  Traits traits(Kernel::Point_3(0, 0, 0), 1.0);
  Triangulation dt(traits);
  Triangulation::Face_handle hint;
  for (const std::size_t i : order) {
    const auto v = dt.insert(Traits::Point_on_sphere_2(sites[i]), hint);
    if (v->index >= 0)
      throw ComputationError(fmt::format("points {} and {} coincide or are too close to triangulate",
                                         std::min<std::size_t>(v->index, i), std::max<std::size_t>(v->index, i)));
    v->index = static_cast<int>(i);
    hint = v->face();
  }
  if (dt.dimension() != 2 || dt.number_of_ghost_faces() != 0)
    throw ComputationError("the points do not span the sphere (all on one hemisphere or great circle)");

  mesh::FaceMatrix faces(static_cast<Eigen::Index>(dt.number_of_solid_faces()), 3);
  Eigen::Index f = 0;
  for (auto face = dt.solid_faces_begin(); face != dt.solid_faces_end(); ++face, ++f)
    for (int k = 0; k < 3; ++k) faces(f, k) = face->vertex(k)->index;
  // CGAL orients faces counter-clockwise seen from outside; check one and flip all if not.
  const Eigen::Vector3d a = points.row(faces(0, 0)), b = points.row(faces(0, 1)), c = points.row(faces(0, 2));
  if ((b - a).cross(c - a).dot(a + b + c) < 0) faces.col(1).swap(faces.col(2));
  return faces;
}

}  // namespace cmp::spheremesh
