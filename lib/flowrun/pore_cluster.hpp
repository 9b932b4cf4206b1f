#pragma once
// The fluid that takes part in the flow (thesis 5.2.2-5.2.3): the connected components of the
// fluid voxels that touch both faces perpendicular to the flow axis, the other two axes
// periodic as the flow's boundaries are. Isolated pockets (and clusters that reach only one
// face) carry no flux; they are dropped and counted.
#include <array>
#include <cstdint>
#include <vector>

namespace cmp::flowrun {

struct PoreCluster {
  std::vector<std::uint8_t> fluid;  // same size as the input mask: 1 = in a spanning component
  long fluid_voxels = 0;            // non-zero voxels of the input
  long cluster_voxels = 0;          // voxels kept
  int components = 0;               // connected components of the input's fluid
  int spanning = 0;                 // of which span the flow axis (kept)
  int dropped_components = 0;       // components - spanning
  long dropped_voxels = 0;          // fluid_voxels - cluster_voxels
};

// Labels mask (dims product bytes, x fastest, non-zero = fluid) with face connectivity (6),
// periodic along the two axes other than axis (0, 1, 2), and keeps the components that touch
// both faces perpendicular to axis. With periodic_axis the flow axis is periodic too (a body
// force in a fully periodic box): a component then still has to touch both of its faces.
// Deterministic for any thread count (voxel::label_components). Throws
// std::invalid_argument for bad dims or mask size.
PoreCluster percolating_cluster(const std::vector<std::uint8_t>& mask, std::array<int, 3> dims, int axis,
                                bool periodic_axis = false);

}  // namespace cmp::flowrun
