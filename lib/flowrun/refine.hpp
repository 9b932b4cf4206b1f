#pragma once
// Lattice refinement (thesis 5.2.3, after its ref. 13): every voxel of the pore image becomes
// M x M x M lattice nodes of side delta / M, so narrow throats get more than one node across.
#include <array>
#include <cstdint>
#include <vector>

namespace cmp::flowrun {

// The mask of an image refined M times: dims * M nodes per axis, node (x, y, z) copies voxel
// (x / M, y / M, z / M); x fastest. Throws std::invalid_argument when M < 1, the mask size
// differs from dims, or the result would pass 2^40 nodes.
std::vector<std::uint8_t> refine_mask(const std::vector<std::uint8_t>& mask, std::array<int, 3> dims, int M);

}  // namespace cmp::flowrun
