#pragma once
// Which components of a labelled image percolate (thesis 5.2.2: "The cluster is said to
// percolate the system if it contains lattice sites on the two opposite sides of the
// simulation box"), reported per axis.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cmp::voxel {

// Faces of the box each component touches.
//   labels  nx*ny*nz labels of label_components (0 = background, 1..count)
// Result: count + 1 bytes; bit 2a of element l is set when component l has a voxel on the
// face where coordinate a is 0, bit 2a + 1 when it has one where coordinate a is n_a - 1.
// Element 0 (the background) is 0. Cost: the six faces only.
std::vector<std::uint8_t> label_face_flags(const std::vector<std::int32_t>& labels, std::array<int, 3> dims, int count);

// Does a component with these face flags touch both faces perpendicular to axis (0, 1, 2)?
inline bool spans(std::uint8_t flags, int axis) { return ((flags >> (2 * axis)) & 3) == 3; }

// One byte per label (count + 1): 1 for the components that span axis, else 0.
std::vector<std::uint8_t> spanning_labels(const std::vector<std::uint8_t>& face_flags, int axis);

// Number of components that span axis.
int spanning_count(const std::vector<std::uint8_t>& face_flags, int axis);

// "x", "y", "z" -> 0, 1, 2; throws cmp::UsageError otherwise.
int axis_from_name(const char* option, const std::string& name);

}  // namespace cmp::voxel
