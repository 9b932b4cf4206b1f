#pragma once
// Checks shared by the tests of the flat benchmark meshes (disc, rectangle, planar Delaunay).
#include "mesh/edge_topology.hpp"
#include "mesh/face_normals.hpp"
#include "mesh/manifold.hpp"
#include "mesh/quality.hpp"
#include "mesh/tri_mesh.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <vector>

namespace cmp::mesh::fixtures {

// A flat open mesh: every face has unit normal +z (counter-clockwise from +z), one connected
// sheet with Euler characteristic 1, manifold, consistently oriented, no unused vertex, smallest
// angle at least min_angle_deg. Returns the set of vertices on boundary edges.
inline std::set<int> check_flat_sheet(const TriMesh& m, double min_angle_deg) {
  const auto rep = manifold_report(m.F, static_cast<int>(m.V.rows()));
  INFO(rep.describe());
  CHECK(rep.nonmanifold_edges == 0);
  CHECK(rep.degenerate_faces == 0);
  CHECK(rep.misoriented_edges == 0);
  CHECK(rep.unused_vertices == 0);
  CHECK(rep.euler_characteristic == 1);
  CHECK(m.V.col(2).cwiseAbs().maxCoeff() == 0.0);
  const auto N = face_normals(m.V, m.F);
  CHECK(N.col(2).minCoeff() == Approx(1.0).epsilon(1e-12));
  const auto q = mesh_quality(m.V, m.F);
  CHECK(q.angle_min * 180 / M_PI >= min_angle_deg);
  std::set<int> boundary;
  const auto topo = edge_topology(m.F);
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e)
    if (topo.edge_face_counts[static_cast<std::size_t>(e)] == 1) boundary.insert({topo.edges(e, 0), topo.edges(e, 1)});
  return boundary;
}

}  // namespace cmp::mesh::fixtures
