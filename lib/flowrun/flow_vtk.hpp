#pragma once
// The flow field as a VTK legacy STRUCTURED_POINTS file (binary, big-endian) that ParaView
// overlays on the packing and on percolate's cluster image: the same origin and length units
// as the input image, the node spacing of the refined lattice. Point data:
//   density   float   rho (lattice units; 0 at solid nodes)
//   velocity  float3  u (lattice units: node sides per time step; 0 at solid nodes)
//   fluid     unsigned_char  1 at the nodes that took part in the flow
// Float, not double: a field to look at; the CSV holds the exact observables.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cmp::flowrun {

struct FlowField {
  std::array<int, 3> dims{0, 0, 0};              // nodes per axis
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();   // node (0, 0, 0) [input length units]
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();  // node side [input length units]
  std::vector<double> velocity;                  // 3 per node, interleaved, x fastest
  std::vector<double> density;                   // 1 per node
  std::vector<std::uint8_t> fluid;               // 1 per node
  std::vector<std::pair<std::string, double>> field_data;  // e.g. delta, d0, refine, kappa_lu
};

// The node lattice of an image refined M times: voxel centres at origin + i * spacing become
// M^3 nodes each, node j at origin + (j + 1/2) spacing / M - spacing / 2 (so M = 1 keeps the
// image's geometry). Returns {node origin, node spacing}.
std::pair<Eigen::Vector3d, Eigen::Vector3d> refined_geometry(const Eigen::Vector3d& origin,
                                                             const Eigen::Vector3d& spacing, int M);

// Writes field to path atomically ("-" = stdout). title is cut to 255 characters. Throws
// std::invalid_argument for arrays whose sizes disagree with dims, cmp::InputError(path, 0,
// ...) when the file cannot be written.
void write_flow_vtk(const std::string& path, const FlowField& field, const std::string& title);

}  // namespace cmp::flowrun
