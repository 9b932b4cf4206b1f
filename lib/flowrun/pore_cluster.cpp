#include "flowrun/pore_cluster.hpp"

#include "voxel/label_components.hpp"
#include "voxel/percolation.hpp"

#include <stdexcept>

namespace cmp::flowrun {

PoreCluster percolating_cluster(const std::vector<std::uint8_t>& mask, std::array<int, 3> dims, int axis,
                                bool periodic_axis) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("percolating_cluster: axis must be 0, 1 or 2");
  if (mask.size() != static_cast<std::size_t>(dims[0]) * dims[1] * dims[2])
    throw std::invalid_argument("percolating_cluster: mask size differs from dims");
  voxel::LabelOptions options;
  options.connectivity = voxel::Connectivity::Faces6;
  options.periodic = {true, true, true};
  options.periodic[axis] = periodic_axis;
  std::vector<std::int32_t> labels;
  PoreCluster out;
  out.components = voxel::label_components(mask.data(), dims, labels, options);
  const auto flags = voxel::label_face_flags(labels, dims, out.components);
  const auto keep = voxel::spanning_labels(flags, axis);
  out.spanning = voxel::spanning_count(flags, axis);
  out.dropped_components = out.components - out.spanning;
  out.fluid.assign(mask.size(), 0);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    out.fluid_voxels += mask[i] != 0;
    if (labels[i] > 0 && keep[static_cast<std::size_t>(labels[i])]) {
      out.fluid[i] = 1;
      ++out.cluster_voxels;
    }
  }
  out.dropped_voxels = out.fluid_voxels - out.cluster_voxels;
  return out;
}

}  // namespace cmp::flowrun
