#pragma once
// One input of lbflow made ready for the flow solver: the lattice of nodes that take part in
// the flow (the percolating cluster, refined M times), where it sits in the input's length
// units, and the units and porosity the output table reports.
//   image (VTK or raw)     -> cluster of the voxels, each voxel M^3 nodes, half-way walls
//   sphere packing (XYZ)   -> nodes outside the spheres on a grid of side delta D0 / M, the
//                             wall distance of every cut link from the exact sphere surfaces
#include "flowrun/flow_image.hpp"
#include "lbm/pore_lattice.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cmp::packing {
struct Packing;
}

namespace cmp::flowrun {

struct FlowCase {
  std::string file;                  // the input as given
  std::string format;                // "vtk", "raw" or "xyz"
  std::string title;                 // the VTK title of the input ("" otherwise)
  std::array<int, 3> voxels{0, 0, 0};  // voxels per axis before refinement
  int refine = 1;                    // M
  int axis = 0;                      // flow axis
  // Node (0, 0, 0) and the node side in the input's length units (lattice units when the
  // input has none: raw bytes, a bare image).
  Eigen::Vector3d node_origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d node_spacing = Eigen::Vector3d::Ones();
  std::optional<double> delta, d0, scale;  // voxel side [D0], D0 [length units], radius factor
  double porosity = 0;               // see porosity_source
  std::string porosity_source;       // "file" (percolate's field data), "sphere_pair_lenses", "voxels"
  double porosity_voxels = 0;        // fluid voxels (nodes for XYZ) / all, pockets included
  long nodes = 0;                    // lattice nodes (all)
  long cluster_nodes = 0;            // nodes that take part in the flow
  int dropped_pockets = 0;           // fluid components that do not span the axis
  long dropped_nodes = 0;            // their nodes
  bool interpolated_walls = false;   // wall fractions from the exact geometry
  lbm::PoreLattice lattice;          // refined; empty until make_lattice() (images), built at once (XYZ)
  std::vector<std::uint8_t> cluster; // images: the voxel-level cluster (refined by make_lattice)

  // Fills `lattice` (images: refines `cluster`; no-op when already built). Separate so that
  // lbflow can check every input before it allocates any lattice.
  void make_lattice();
  // Frees the lattice (the next case can reuse the memory).
  void release_lattice();
};

// The case of an image: the voxels that percolate along axis with periodic sides (the flow
// axis too with periodic_axis, for body-force driving), refined M times. Throws
// cmp::ComputationError "FILE: no fluid cluster spans the image along x (N fluid voxels in
// K clusters): nothing can flow" when none does.
FlowCase image_case(const FlowImage& image, int M, int axis, bool periodic_axis);

// The case of a sphere packing (radii already scaled): a grid of round(L / (delta D0)) voxels
// per axis as percolate's, each M^3 nodes; a node is fluid when its centre lies outside every
// sphere (periodic images included; the packing must be periodic on every axis), then the
// cluster as for images; wall fractions from the spheres (lbm::periodic_spheres). porosity
// is the geometric one (pair lenses, as percolate's). Throws cmp::UsageError when delta D0
// passes the box, cmp::InputError for a packing that is not periodic on every axis, and
// cmp::ComputationError as image_case.
FlowCase sphere_case(const packing::Packing& packing, double delta, int M, int axis, bool periodic_axis);

// How lbflow reads an input.
struct InputOptions {
  std::string dims;          // non-empty: raw bytes of these dimensions ("96x96x96")
  int refine = 3;            // M
  double delta = 0;          // sphere packings: voxel side [D0] (required for them)
  double scale = 1, d0 = 0;  // sphere packings: radius factor; D0 (0: the file's, else the mean diameter)
  int axis = 0;
  bool periodic_axis = false;
};

// The case of one input, its format told from the content (io::Input) unless dims says raw
// bytes: a VTK image, an extended XYZ sphere packing (one frame), or raw bytes; "-" reads a
// VTK image or raw bytes from stdin. Throws cmp::InputError for anything else or a bad file,
// cmp::UsageError for a packing without delta, and what image_case and sphere_case throw.
FlowCase read_flow_case(const std::string& path, const InputOptions& options);

// The cases of one input at several refinements M (ascending), read once: one case per M, but a
// coarse M at which nothing spans the axis (a sphere packing whose throats close on the coarser
// grid) is left out and said in `skipped` ("M = 1 skipped: FILE: no fluid cluster spans ...").
// Throws as read_flow_case, and its ComputationError when nothing spans at the finest M.
struct RefinementCases {
  std::vector<FlowCase> cases;
  std::vector<std::string> skipped;
};
RefinementCases read_flow_cases(const std::string& path, const InputOptions& options, const std::vector<int>& refinements);

// lbflow's relaxation time when none is asked for. With half-way walls (images) the steady flow
// of `mrt` and `trt` hardly depends on tau (kappa within 3e-5 from tau = 0.55 to 1 on a jammed
// cluster at porosity 0.175, 1e-4 on Zick & Homsy's sphere array), while the slow settling of
// the pressure along a barely connected cluster takes steps in proportion to the viscosity
// (tau - 1/2)/3: 0.55 settles 5-7 times sooner than 1; below 0.55 kappa starts to move (2e-4 at
// 0.52). Interpolated walls (sphere packings) move with tau (2.4 % from 1 to 0.55 on the sphere
// array): they keep the thesis's tau = 1.
double default_tau(const FlowCase& c);

// "x", "y", "z".
const char* axis_name(int axis);

}  // namespace cmp::flowrun
