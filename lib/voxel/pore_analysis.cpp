#include "voxel/pore_analysis.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "voxel/hydraulic_radius.hpp"
#include "voxel/percolation.hpp"
#include "packing/shell_volumes.hpp"
#include "voxel/porosity.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>

namespace cmp::voxel {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

GeometricPorosity geometric_porosity(const packing::Packing& p) {
  GeometricPorosity out;
  const double box_volume = p.box.prod();
  if (p.kind == packing::Packing::Kind::Shells) {
    double v = 0;
    for (double s : packing::shell_volumes(p.V, p.F, p.shell_offsets)) v += s;
    out.method = "shell_volumes";
    out.particle_volume_fraction = v / box_volume;
    out.porosity = std::clamp(1 - out.particle_volume_fraction, 0.0, 1.0);
    out.exact = out.porosity == 1 - out.particle_volume_fraction;  // else shells overlap (or face inwards)
    return out;
  }
  const auto v = sphere_volumes(p.centres, p.radii, p.box, p.periodic);
  out.method = "sphere_pair_lenses";
  out.particle_volume_fraction = v.total / box_volume;
  out.porosity = std::clamp(1 - (v.total - v.pair_overlap) / box_volume, 0.0, 1.0);  // >= 0 (Bonferroni) but for rounding
  out.exact = v.pair_correction_exact();
  out.triple_overlaps = v.triple_overlaps;
  out.image_overlaps = v.image_overlaps;
  return out;
}

PoreAnalysis analyse_pores(const packing::Packing& p, double delta, const PoreAnalysisOptions& o, std::vector<std::uint8_t>* cluster) {
  PoreAnalysis a;
  a.flow_axis = o.flow_axis;
  try {
    a.grid = make_grid(p.box, delta * p.d0, p.periodic);
  } catch (const UsageError& e) {
    throw UsageError(p.file + ": " + e.what() + " [length units of the file; D0 = " + io::format_number(p.d0) + "]");
  }
  const VoxelGrid& g = a.grid;
  a.delta_actual = g.spacing / p.d0;

  double t0 = now();
  std::vector<std::uint8_t> pore(g.size(), 1);
  if (p.kind == packing::Packing::Kind::Shells) {
    mark_shells(p.V, p.F, g, o.shell_marking, o.thickness * p.d0, pore);
    a.marking = shell_marking_name(o.shell_marking);
    if (o.thickness > 0) a.marking += "+" + io::format_number(o.thickness);
  } else {
    mark_spheres(p.centres, p.radii, g, o.sphere_marking, pore);
    a.marking = "spheres-" + sphere_marking_name(o.sphere_marking);
  }
  a.geometry = geometric_porosity(p);
  a.porosity_voxels = voxel_porosity(pore);
  a.void_voxels = static_cast<long>(std::llround(a.porosity_voxels * static_cast<double>(g.size())));  // exact below 2^53
  double t1 = now();
  a.seconds_marking = t1 - t0;

  // One labelling for every axis (scipy's way), or one per axis with the other two periodic;
  // the flow axis last, so its labels stay for the surface and the cluster image.
  std::vector<std::int32_t> labels;
  LabelOptions lo;
  lo.connectivity = o.connectivity;
  std::vector<int> order;
  for (int ax = 0; ax < 3; ++ax)
    if (ax != o.flow_axis) order.push_back(ax);
  order.push_back(o.flow_axis);
  std::vector<std::uint8_t> flags;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int ax = order[k];
    if (!o.periodic_perpendicular && k + 1 < order.size()) continue;  // the last labelling serves all
    lo.periodic = {false, false, false};
    if (o.periodic_perpendicular)
      for (int b = 0; b < 3; ++b) lo.periodic[b] = b != ax && g.periodic[b];
    a.clusters = label_components(pore.data(), g.dims, labels, lo);
    flags = label_face_flags(labels, g.dims, a.clusters);
    for (int b = 0; b < 3; ++b)
      if (!o.periodic_perpendicular || b == ax) {
        a.spanning_clusters[b] = spanning_count(flags, b);
        a.percolates[b] = a.spanning_clusters[b] > 0;
      }
  }
  a.seconds_labelling = now() - t1;

  const auto selected = spanning_labels(flags, o.flow_axis);
  const auto s = cluster_surface(pore, labels, selected, g);
  a.cluster_voxels = s.volume;
  a.surface_sites = s.surface_sites;
  a.exposed_faces = s.total_exposed_faces();
  a.rh_sites_voxels = s.radius_sites_voxels();
  a.rh_faces_voxels = s.radius_faces_voxels();
  a.rh_sites_d0 = s.radius_sites(g) / p.d0;
  a.rh_faces_d0 = s.radius_faces(g) / p.d0;
  if (cluster) {
    const long n = static_cast<long>(g.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) pore[i] = selected[labels[i]];
    *cluster = std::move(pore);
  }
  return a;
}

std::vector<std::pair<std::string, std::string>> pore_analysis_fields(const PoreAnalysis& a) {
  using io::format_number;
  const auto& g = a.grid;
  const double total = static_cast<double>(g.size());
  auto b = [](bool v) { return std::string(v ? "1" : "0"); };
  return {
      {"nx", std::to_string(g.dims[0])},
      {"ny", std::to_string(g.dims[1])},
      {"nz", std::to_string(g.dims[2])},
      {"delta_x_d0", format_number(a.delta_actual[0])},
      {"delta_y_d0", format_number(a.delta_actual[1])},
      {"delta_z_d0", format_number(a.delta_actual[2])},
      {"marking", a.marking},
      {"porosity", format_number(a.geometry.porosity)},
      {"porosity_method", a.geometry.method},
      {"porosity_exact", b(a.geometry.exact)},
      {"particle_volume_fraction", format_number(a.geometry.particle_volume_fraction)},
      {"porosity_voxels", format_number(a.porosity_voxels)},
      {"clusters", std::to_string(a.clusters)},
      {"percolates_x", b(a.percolates[0])},
      {"percolates_y", b(a.percolates[1])},
      {"percolates_z", b(a.percolates[2])},
      {"flow_axis", std::string(1, "xyz"[a.flow_axis])},
      {"percolates", b(a.percolates[a.flow_axis])},
      {"spanning_clusters", std::to_string(a.spanning_clusters[a.flow_axis])},
      {"cluster_voxels", std::to_string(a.cluster_voxels)},
      {"cluster_fraction", format_number(a.cluster_voxels / total)},
      {"cluster_fraction_of_void", format_number(a.void_voxels > 0 ? a.cluster_voxels / static_cast<double>(a.void_voxels) : 0.0)},
      {"surface_sites", std::to_string(a.surface_sites)},
      {"exposed_faces", std::to_string(a.exposed_faces)},
      {"rh_sites_delta", format_number(a.rh_sites_voxels)},
      {"rh_faces_delta", format_number(a.rh_faces_voxels)},
      {"rh_sites_d0", format_number(a.rh_sites_d0)},
      {"rh_faces_d0", format_number(a.rh_faces_d0)},
  };
}

}  // namespace cmp::voxel
