#include "voxel/percolation.hpp"

#include "core/errors.hpp"

namespace cmp::voxel {

std::vector<std::uint8_t> label_face_flags(const std::vector<std::int32_t>& labels, std::array<int, 3> dims, int count) {
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(count) + 1, 0);
  const long nx = dims[0], ny = dims[1], nz = dims[2];
  auto at = [&](long x, long y, long z) { return labels[static_cast<std::size_t>(x + nx * (y + ny * z))]; };
  for (long z = 0; z < nz; ++z)
    for (long y = 0; y < ny; ++y) {
      flags[at(0, y, z)] |= 1;
      flags[at(nx - 1, y, z)] |= 2;
    }
  for (long z = 0; z < nz; ++z)
    for (long x = 0; x < nx; ++x) {
      flags[at(x, 0, z)] |= 4;
      flags[at(x, ny - 1, z)] |= 8;
    }
  for (long y = 0; y < ny; ++y)
    for (long x = 0; x < nx; ++x) {
      flags[at(x, y, 0)] |= 16;
      flags[at(x, y, nz - 1)] |= 32;
    }
  flags[0] = 0;
  return flags;
}

std::vector<std::uint8_t> spanning_labels(const std::vector<std::uint8_t>& face_flags, int axis) {
  std::vector<std::uint8_t> s(face_flags.size(), 0);
  for (std::size_t l = 1; l < face_flags.size(); ++l) s[l] = spans(face_flags[l], axis);
  return s;
}

int spanning_count(const std::vector<std::uint8_t>& face_flags, int axis) {
  int n = 0;
  for (std::size_t l = 1; l < face_flags.size(); ++l) n += spans(face_flags[l], axis);
  return n;
}

int axis_from_name(const char* option, const std::string& name) {
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "z") return 2;
  throw UsageError(std::string(option) + " must be x, y or z, got '" + name + "'");
}

}  // namespace cmp::voxel
