#pragma once
// The cubic lattice a packing is projected on (thesis 5.2.2): a box [0, L) cut into voxels of
// side close to delta. When L / delta is not a whole number the grid has
// n = round(L / delta) voxels along that axis and the actual spacing L / n is reported.
#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace cmp::voxel {

struct VoxelGrid {
  Eigen::Vector3d box = Eigen::Vector3d::Ones();      // box sides [length units]
  std::array<int, 3> dims{1, 1, 1};                    // voxels per axis
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();  // box[a] / dims[a] [length units]
  std::array<bool, 3> periodic{true, true, true};     // the packing wraps around this axis

  std::size_t size() const { return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; }
  // Voxel (i, j, k) covers [i h_x, (i+1) h_x) x [j h_y, ...) x [k h_z, ...) and is element
  // i + n_x (j + n_y k) of an image (x fastest, as io::VoxelImage).
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
  }
};

// The grid of voxels of side ~delta on the box [0, box).
//   box       3 positive box sides [length units]
//   delta     requested voxel side [same units]
//   periodic  per-axis periodic flags of the packing
// Result: dims[a] = max(1, round(box[a] / delta)), spacing[a] = box[a] / dims[a], so the
// actual spacing differs from delta by at most a factor 1 +- delta / (2 box[a]).
// Throws cmp::UsageError when delta is not positive and finite, when it is larger than the
// smallest box side, or when the grid would have 2^31 - 1 voxels or more (labels are int32).
VoxelGrid make_grid(const Eigen::Vector3d& box, double delta, std::array<bool, 3> periodic = {true, true, true});

}  // namespace cmp::voxel
