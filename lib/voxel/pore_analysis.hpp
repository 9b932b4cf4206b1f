#pragma once
// The whole of percolate for one packing and one delta: voxelise, label the void, find the
// clusters spanning each axis, measure porosity and the hydraulic radius of the cluster that
// spans the flow axis, and hand back that cluster as an image (the input of lbflow).
#include "voxel/grid.hpp"
#include "voxel/label_components.hpp"
#include "voxel/packing.hpp"
#include "voxel/solid_marking.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cmp::voxel {

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
  double porosity_geometry = 0;    // 1 - sum V / V_box (thesis)
  double porosity_geometry_overlap = 0;  // spheres: 1 - (sum V - pair lenses) / V_box; shells: same as above
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
  double seconds_marking = 0, seconds_labelling = 0;
};

// Analyses packing at voxel side delta [D_0]. When cluster is given it receives the grid's
// voxels: 1 in the clusters spanning the flow axis, 0 elsewhere (memory: the pore image
// becomes this, so the peak is one byte plus one label per voxel). Throws cmp::UsageError for
// a delta that make_grid rejects (naming the file).
PoreAnalysis analyse_pores(const Packing& packing, double delta, const PoreAnalysisOptions& options,
                           std::vector<std::uint8_t>* cluster = nullptr);

// Column names and values of one CSV row (units in the names).
std::vector<std::pair<std::string, std::string>> pore_analysis_fields(const PoreAnalysis& a);

}  // namespace cmp::voxel
