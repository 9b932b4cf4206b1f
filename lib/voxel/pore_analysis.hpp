#pragma once
// The whole of percolate for one packing and one delta: voxelise, label the void, find the
// clusters spanning each axis, measure porosity and the hydraulic radius of the cluster that
// spans the flow axis, and hand back that cluster as an image (the input of lbflow).
#include "voxel/grid.hpp"
#include "voxel/label_components.hpp"
#include "packing/packing_file.hpp"
#include "voxel/solid_marking.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cmp::voxel {

// The one geometric porosity percolate reports (CSV column porosity) and how it was found.
struct GeometricPorosity {
  double porosity = 0;                  // in [0, 1]
  std::string method;                   // "shell_volumes" or "sphere_pair_lenses"
  bool exact = true;                    // false: spheres where the pair-lens correction is not exact
  double particle_volume_fraction = 0;  // sum V / V_box (> 1 possible for overlapping spheres)
  long triple_overlaps = 0, image_overlaps = 0;  // spheres: see SphereVolumes
};
// Shells: 1 - sum of enclosed shell volumes / V_box ("shell_volumes", exact for shells that do
// not overlap; clamped to [0, 1] with exact = false when they must). Spheres: 1 - (sum V - sum of pair lenses) / V_box ("sphere_pair_lenses"), exact
// while no point is in three spheres and no sphere or pair overlaps its own periodic image;
// otherwise an upper bound of the true porosity (Bonferroni), capped at 1, with exact = false.
GeometricPorosity geometric_porosity(const packing::Packing& packing);

struct PoreAnalysisOptions {
  ShellMarking shell_marking = ShellMarking::Triangles;
  SphereMarking sphere_marking = SphereMarking::Overlap;
  double thickness = 0;  // shells: thickening radius [D_0]
  Connectivity connectivity = Connectivity::Faces6;
  // Label with periodic faces perpendicular to the axis tested (LB's boundaries); false is
  // scipy.ndimage.label as the thesis used it (one labelling for all three axes).
  bool periodic_perpendicular = false;
  int flow_axis = 0;  // 0, 1, 2: the cluster returned and measured spans this axis
};

struct PoreAnalysis {
  VoxelGrid grid;                  // in length units of the file
  Eigen::Vector3d delta_actual;    // grid.spacing / D_0
  std::string marking;             // "triangles", "vertices", "spheres-overlap", ... (+thickness)
  GeometricPorosity geometry;      // the porosity of the packing itself (no voxels)
  double porosity_voxels = 0;      // void voxels / voxels
  int flow_axis = 0;
  int clusters = 0;                // components of the void (of the flow-axis labelling)
  std::array<bool, 3> percolates{false, false, false};
  std::array<int, 3> spanning_clusters{0, 0, 0};
  long void_voxels = 0;
  long cluster_voxels = 0;         // voxels of the clusters spanning the flow axis
  long surface_sites = 0;
  long exposed_faces = 0;
  double rh_sites_voxels = 0, rh_faces_voxels = 0;  // [delta]
  double rh_sites_d0 = 0, rh_faces_d0 = 0;          // [D_0]
  double seconds_marking = 0, seconds_labelling = 0;  // wall clock (never in the CSV: see --timings)
};

// Analyses packing at voxel side delta [D_0]. When cluster is given it receives the grid's
// voxels: 1 in the clusters spanning the flow axis, 0 elsewhere (memory: the pore image
// becomes this, so the peak is one byte plus one label per voxel). Throws cmp::UsageError for
// a delta that make_grid rejects (naming the file).
PoreAnalysis analyse_pores(const packing::Packing& packing, double delta, const PoreAnalysisOptions& options,
                           std::vector<std::uint8_t>* cluster = nullptr);

// Column names and values of one CSV row (units in the names), from nx to rh_faces_d0; no
// timings, so the same input gives the same bytes.
std::vector<std::pair<std::string, std::string>> pore_analysis_fields(const PoreAnalysis& a);

}  // namespace cmp::voxel
