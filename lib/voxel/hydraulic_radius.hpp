#pragma once
// Hydraulic radius of a cluster: its volume over its wetted surface (thesis 5.3.2, Fig. 5.3).
// The surface is counted two ways: surface sites (cluster voxels with at
// least one solid face neighbour, the thesis's "number of surface sites") and exposed faces
// (voxel faces between the cluster and the solid, the area in units of delta^2).
#include "voxel/grid.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cmp::voxel {

struct ClusterSurface {
  long volume = 0;                    // cluster voxels
  long surface_sites = 0;             // cluster voxels with a solid face neighbour
  std::array<long, 3> exposed_faces{0, 0, 0};  // cluster-solid voxel faces normal to x, y, z

  long total_exposed_faces() const { return exposed_faces[0] + exposed_faces[1] + exposed_faces[2]; }
  // Volume / surface sites [voxels]; 0 when there is no surface.
  double radius_sites_voxels() const;
  // Volume / exposed faces [voxel sides]; 0 when there is no surface.
  double radius_faces_voxels() const;
  // The same in the grid's length units: sites x mean spacing; faces as volume / area with the
  // actual voxel sides (they differ slightly per axis when L/delta is not whole).
  double radius_sites(const VoxelGrid& grid) const;
  double radius_faces(const VoxelGrid& grid) const;
};

// Volume and wetted surface of the selected components.
//   pore      grid.size() bytes, 0 = solid
//   labels    grid.size() labels of the void (label_components), 0 on solid voxels
//   selected  one byte per label (count + 1): nonzero for the components to measure
// A neighbour across the box face is the voxel on the other side along periodic axes of the
// grid (the packing continues there) and counts as not solid along the others (no wall).
// Parallel over z; the counts do not depend on the thread count.
ClusterSurface cluster_surface(const std::vector<std::uint8_t>& pore, const std::vector<std::int32_t>& labels,
                               const std::vector<std::uint8_t>& selected, const VoxelGrid& grid);

}  // namespace cmp::voxel
