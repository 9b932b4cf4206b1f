#pragma once
// Voxel images as VTK legacy STRUCTURED_POINTS files (docs/formats.md), which ParaView opens:
//   # vtk DataFile Version 3.0
//   <title: tool, version, command line>
//   BINARY
//   DATASET STRUCTURED_POINTS
//   DIMENSIONS nx ny nz
//   ORIGIN ox oy oz
//   SPACING dx dy dz
//   FIELD FieldData n          (optional: dataset-level values, e.g. delta and D0;
//   <name> 1 1 double           one such array per value, written as the data are:
//   <the value>                  big-endian binary in a BINARY file)
//   POINT_DATA nx*ny*nz
//   SCALARS <name> <type> 1
//   LOOKUP_TABLE default
//   <nx*ny*nz values, big-endian as the legacy format requires, x fastest>
#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace cmp::io {

// The scalar types a voxel image may hold, with their names in a VTK file.
template <class T>
concept VtkScalar = std::same_as<T, std::uint8_t> || std::same_as<T, std::int32_t> ||
    std::same_as<T, float> || std::same_as<T, double>;

// "unsigned_char", "int", "float" or "double".
template <VtkScalar T>
constexpr const char* vtk_type_name() {
  if constexpr (std::same_as<T, std::uint8_t>)
    return "unsigned_char";
  else if constexpr (std::same_as<T, std::int32_t>)
    return "int";
  else if constexpr (std::same_as<T, float>)
    return "float";
  else
    return "double";
}

// A scalar field on a regular grid of points: voxel (x, y, z) sits at
// origin + (x*spacing[0], y*spacing[1], z*spacing[2]) and is data[x + nx*(y + ny*z)].
template <VtkScalar T>
struct VoxelImage {
  std::array<int, 3> dims{0, 0, 0};  // nx, ny, nz (points per axis)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();  // e.g. delta on every axis
  std::string name = "values";                        // SCALARS name (no whitespace)
  std::vector<T> data;                                // x fastest, then y, then z
  // Dataset-level values (legacy FIELD FieldData, one 1x1 double array each), e.g.
  // {"delta", 0.04}, {"D0", 1.02}: names without whitespace, finite values. ParaView shows
  // them as field data; a file without FIELD reads back with none.
  std::vector<std::pair<std::string, double>> field_data;

  VoxelImage() = default;
  // An nx by ny by nz image filled with fill.
  explicit VoxelImage(std::array<int, 3> d, T fill = T{})
      : dims(d), data(static_cast<std::size_t>(d[0]) * d[1] * d[2], fill) {}

  std::size_t size() const { return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; }
  // Position of voxel (x, y, z) in data; no bounds check.
  std::size_t index(int x, int y, int z) const {
    return static_cast<std::size_t>(x) +
           static_cast<std::size_t>(dims[0]) *
               (static_cast<std::size_t>(y) + static_cast<std::size_t>(dims[1]) * z);
  }
  T& operator()(int x, int y, int z) { return data[index(x, y, z)]; }
  const T& operator()(int x, int y, int z) const { return data[index(x, y, z)]; }
};

// What the header of a VTK file says, without the data.
struct VtkInfo {
  std::string title;
  bool binary = true;  // BINARY, else ASCII
  std::array<int, 3> dims{0, 0, 0};
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  std::string name;       // SCALARS name
  std::string type;       // SCALARS type in lower case, e.g. "unsigned_char"
  long scalars_line = 0;  // line of the SCALARS keyword
  long data_line = 0;     // line where the values start
  // FIELD arrays of one value (other FIELD arrays are read and skipped).
  std::vector<std::pair<std::string, double>> field_data;

  std::size_t size() const { return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; }
};

// Reads and checks the header of a STRUCTURED_POINTS file ("-" = stdin) with one
// single-component SCALARS field on POINT_DATA. Throws cmp::InputError(file, line, ...) for a
// missing version line, an unknown ASCII/BINARY line, another DATASET, dimensions that are not
// 3 positive integers, a spacing that is not 3 positive numbers, POINT_DATA disagreeing with
// the dimensions, CELL_DATA, a missing LOOKUP_TABLE or more than one component, dimensions
// whose product (checked in 64 bits) passes 2^40 points, a malformed FIELD block or a FIELD
// value that is not finite, a SPACING whose extent (or square) overflows a double.
VtkInfo read_vtk_info(const std::string& path);

class Input;

// Reads the image ("-" = stdin), BINARY or ASCII. Throws as read_vtk_info, and
// cmp::InputError when the SCALARS type is not vtk_type_name<T>() (naming the type found),
// the data are truncated (a regular file too short for the image is refused before anything
// is allocated; from a pipe memory grows as the bytes arrive), an ASCII value does not fit T,
// or anything but whitespace follows the data.
template <VtkScalar T>
VoxelImage<T> read_vtk(const std::string& path);
// Same, from an opened input.
template <VtkScalar T>
VoxelImage<T> read_vtk(Input& input);

// An image of any of the scalar types, read in one pass (standard input): the type is the
// one its SCALARS line names.
using AnyVoxelImage =
    std::variant<VoxelImage<std::uint8_t>, VoxelImage<std::int32_t>, VoxelImage<float>, VoxelImage<double>>;
AnyVoxelImage read_vtk_any(Input& input);

// Writes the image as BINARY atomically (see AtomicOutput; "-" = stdout). title is cut to
// 255 characters, line breaks become spaces. Converts to big-endian chunk by chunk, so memory
// stays at the image plus 64k values. Throws std::invalid_argument when data.size() is not
// nx*ny*nz, a dimension is < 1, spacing is not positive and finite, origin is not finite,
// name or a field_data name is empty or holds whitespace; cmp::ComputationError (exit 1: a
// computed quantity went wrong) when a field_data value is not finite; cmp::InputError(path,
// 0, ...) when the file cannot be written.
template <VtkScalar T>
void write_vtk(const std::string& path, const VoxelImage<T>& image, const std::string& title);

// Same, to a stream (no atomicity).
template <VtkScalar T>
void write_vtk(std::ostream& out, const VoxelImage<T>& image, const std::string& title);

}  // namespace cmp::io
