#pragma once
// Connected components of the nonzero voxels of a 3D image, as scipy.ndimage.label (what the
// thesis used, 5.2.2) computes them, optionally periodic along chosen axes. The hot loop of
// percolate: run-based union-find on the label array itself, in parallel over z slabs.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cmp::voxel {

// Which neighbours are connected: faces (6, scipy's default structuring element
// generate_binary_structure(3, 1)), faces and edges (18, rank 2), or all 26 (rank 3).
enum class Connectivity { Faces6 = 6, Edges18 = 18, Corners26 = 26 };

// "6", "18" or "26"; throws cmp::UsageError for anything else.
Connectivity connectivity_from_name(const std::string& name);

struct LabelOptions {
  Connectivity connectivity = Connectivity::Faces6;
  // Voxels on opposite faces of a periodic axis are neighbours (with the same connectivity
  // across the boundary). scipy.ndimage.label has no such option: all false reproduces it.
  std::array<bool, 3> periodic{false, false, false};
};

// Labels the connected components of the voxels where image != 0.
//   image   nx*ny*nz bytes, x fastest (image[x + nx (y + ny z)]), as io::VoxelImage
//   dims    nx, ny, nz (each >= 1, nx*ny*nz < 2^31 - 1)
//   labels  output, resized to nx*ny*nz: 0 where image == 0, else 1..count
// Returns count, the number of components. Components are numbered in the order of their
// first voxel in memory order (x fastest), as scipy numbers them for an array indexed
// [z, y, x]; so the result depends neither on the thread count nor on timing.
// Cost: O(N) time, one pass over the image, two over the labels and a few over the run
// starts; memory: the labels (4 bytes per voxel) and one bit per voxel (the image's rows as
// bit masks). Uses all OpenMP threads (one z slab each).
// Throws std::invalid_argument for bad dims.
int label_components(const std::uint8_t* image, std::array<int, 3> dims, std::vector<std::int32_t>& labels,
                     const LabelOptions& options = {});

}  // namespace cmp::voxel
