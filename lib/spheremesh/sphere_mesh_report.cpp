#include "spheremesh/sphere_mesh_report.hpp"

#include "io/csv.hpp"
#include "mesh/edge_curvature.hpp"
#include "mesh/edge_topology.hpp"
#include "mesh/enclosed_volume.hpp"
#include "mesh/face_areas.hpp"
#include "mesh/manifold.hpp"
#include "mesh/quality.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::spheremesh {

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double sum = 0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

std::vector<double> finite_ratios(const Eigen::VectorXd& radii, double scale) {
  std::vector<double> out;
  for (double r : radii)
    if (std::isfinite(r)) out.push_back(r / scale);
  return out;
}
}  // namespace

SphereMeshReport sphere_mesh_report(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F) {
  SphereMeshReport r;
  const auto topology = mesh::manifold_report(F, static_cast<int>(V.rows()));
  r.vertices = V.rows();
  r.faces = F.rows();
  r.edges = topology.edges;
  r.euler_characteristic = topology.euler_characteristic;
  r.closed_manifold = topology.closed_manifold();
  r.consistently_oriented = topology.consistently_oriented();

  const auto q = mesh::mesh_quality(V, F);
  r.q_area = q.q_area, r.q_angle = q.q_angle, r.q_radius_ratio = q.q_radius_ratio;
  r.dual_area_min = q.dual_area_min, r.dual_area_max = q.dual_area_max;
  r.angle_min_deg = q.angle_min * 180 / M_PI, r.angle_max_deg = q.angle_max * 180 / M_PI;
  r.radius_ratio_mean = q.radius_ratio_mean, r.low_quality_fraction = q.low_quality_fraction;

  const Eigen::RowVector3d centroid = V.colwise().mean();
  r.mean_radius = (V.rowwise() - centroid).rowwise().norm().mean();
  r.area = mesh::total_area(V, F);
  r.volume_tetra = mesh::enclosed_volume(V, F, mesh::VolumeMethod::CentroidTetrahedra);
  r.volume_divergence = mesh::enclosed_volume(V, F, mesh::VolumeMethod::DivergenceTheorem);
  const double sphere_area = 4 * M_PI * r.mean_radius * r.mean_radius;
  const double sphere_volume = sphere_area * r.mean_radius / 3;
  r.area_rel_error = r.area / sphere_area - 1;
  r.volume_tetra_rel_error = r.volume_tetra / sphere_volume - 1;
  r.volume_divergence_rel_error = r.volume_divergence / sphere_volume - 1;

  const auto thesis = finite_ratios(mesh::edge_curvature_radii(V, F, mesh::CurvatureEstimator::ThesisA7), r.mean_radius);
  r.flat_edges = r.edges - static_cast<long>(thesis.size());
  r.curvature_min = thesis.empty() ? NAN : *std::min_element(thesis.begin(), thesis.end());
  r.curvature_max = thesis.empty() ? NAN : *std::max_element(thesis.begin(), thesis.end());
  r.curvature_median = median(thesis);
  r.curvature_mean = mean(thesis);
  // The centroid-distance estimator is Eq. A.7 times (h1+h2)/3 over (h1+h2)/2, edge by edge.
  r.curvature_centroid_mean = mean(thesis) * (2.0 / 3.0);
  return r;
}

std::vector<std::pair<std::string, std::string>> report_fields(const SphereMeshReport& r) {
  auto num = [](double x) { return io::format_number(x); };
  auto integer = [](long x) { return std::to_string(x); };
  return {
      {"vertices", integer(r.vertices)},
      {"faces", integer(r.faces)},
      {"edges", integer(r.edges)},
      {"euler_characteristic", integer(r.euler_characteristic)},
      {"closed_manifold", integer(r.closed_manifold)},
      {"consistently_oriented", integer(r.consistently_oriented)},
      {"q_A", num(r.q_area)},
      {"q_theta", num(r.q_angle)},
      {"q", num(r.q_radius_ratio)},
      {"dual_area_min_u2", num(r.dual_area_min)},
      {"dual_area_max_u2", num(r.dual_area_max)},
      {"angle_min_deg", num(r.angle_min_deg)},
      {"angle_max_deg", num(r.angle_max_deg)},
      {"radius_ratio_mean", num(r.radius_ratio_mean)},
      {"low_quality_fraction", num(r.low_quality_fraction)},
      {"mean_radius_u", num(r.mean_radius)},
      {"area_u2", num(r.area)},
      {"area_rel_error", num(r.area_rel_error)},
      {"volume_tetra_u3", num(r.volume_tetra)},
      {"volume_tetra_rel_error", num(r.volume_tetra_rel_error)},
      {"volume_divergence_u3", num(r.volume_divergence)},
      {"volume_divergence_rel_error", num(r.volume_divergence_rel_error)},
      {"curvature_radius_min_rel", num(r.curvature_min)},
      {"curvature_radius_mean_rel", num(r.curvature_mean)},
      {"curvature_radius_median_rel", num(r.curvature_median)},
      {"curvature_radius_max_rel", num(r.curvature_max)},
      {"curvature_radius_centroid_mean_rel", num(r.curvature_centroid_mean)},
      {"flat_edges", integer(r.flat_edges)},
  };
}

}  // namespace cmp::spheremesh
