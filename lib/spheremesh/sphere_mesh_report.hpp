#pragma once
// Everything Appendix A measures of a sphere mesh, in one record: counts and topology,
// quality (A.3.1), area and volume by both methods against the ideal sphere (A.3.2, A.4.1),
// and the curvature-radius estimate (A.3.3). Works on any triangle mesh; the sphere
// comparisons use the sphere of the mesh's mean vertex distance from its vertex centroid.
#include "mesh/tri_mesh.hpp"
#include <string>
#include <utility>
#include <vector>

namespace cmp::spheremesh {

struct SphereMeshReport {
  long vertices = 0, faces = 0, edges = 0, euler_characteristic = 0;
  bool closed_manifold = false, consistently_oriented = false;
  double q_area = 0, q_angle = 0, q_radius_ratio = 0;
  double dual_area_min = 0, dual_area_max = 0, angle_min_deg = 0, angle_max_deg = 0;
  double radius_ratio_mean = 0, low_quality_fraction = 0;
  double mean_radius = 0;
  double area = 0, volume_tetra = 0, volume_divergence = 0;
  double area_rel_error = 0, volume_tetra_rel_error = 0, volume_divergence_rel_error = 0;
  // R_est / mean_radius over the interior, non-flat edges (Eq. A.7 as printed), and the
  // median of the centroid-distance estimator (see mesh/edge_curvature.hpp).
  double curvature_min = 0, curvature_mean = 0, curvature_median = 0, curvature_max = 0;
  double curvature_centroid_mean = 0;
  long flat_edges = 0;  // edges whose two faces are coplanar: no finite estimate
};

//   V  #V by 3, F  #F by 3 (F non-empty)
SphereMeshReport sphere_mesh_report(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F);

// The report as (column, value) pairs, units in the column names (u = the mesh's length unit):
// the CSV columns of `rndmesh stats` and the "# key=value" lines rndmesh writes into its OFF.
std::vector<std::pair<std::string, std::string>> report_fields(const SphereMeshReport& r);

}  // namespace cmp::spheremesh
