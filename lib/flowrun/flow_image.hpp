#pragma once
// The pore image lbflow reads: a binary VTK STRUCTURED_POINTS image (what percolate writes,
// or any such image: non-zero = fluid) or raw bytes with their dimensions given, as a fluid
// mask with its geometry and the units percolate records in the file's field data.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cmp::io {
class Input;
}

namespace cmp::flowrun {

struct FlowImage {
  std::string file;                    // as given ("-" = stdin)
  std::string format;                  // "vtk" or "raw"
  std::array<int, 3> dims{0, 0, 0};    // voxels per axis
  std::vector<std::uint8_t> fluid;     // dims product, x fastest; 1 = fluid (non-zero voxel), 0 = solid
  // Voxel (x, y, z) is centred at origin + (x, y, z) * spacing, in the file's length units
  // (raw bytes and images that say nothing: origin 0, spacing 1, i.e. lattice units).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  // From the VTK field data as percolate writes them (absent: nullopt):
  std::optional<double> delta;         // voxel side [D0]
  std::optional<double> d0;            // D0 [length units of the file]
  std::optional<double> scale;         // radius factor of an inflated sphere packing
  std::optional<double> porosity;      // geometric porosity of the packing (no voxels)
  std::string title;                   // the VTK title line ("" for raw bytes)

  std::size_t size() const { return fluid.size(); }
  long fluid_voxels() const;           // non-zero voxels
};

// "96x96x96" -> {96, 96, 96}; each a positive integer. Throws cmp::UsageError
// ("--dims: expected NXxNYxNZ, e.g. 96x96x96, got '...'") otherwise, or when the product
// passes 2^40.
std::array<int, 3> parse_dims(const std::string& text);

// Reads a VTK image (every scalar type VTK's legacy writer gives that io::read_vtk reads:
// unsigned_char, int, float, double; non-zero = fluid) from path ("-" = stdin). Throws
// cmp::InputError(path, line, ...) as io::read_vtk does (not STRUCTURED_POINTS, CELL_DATA,
// truncated data, ...), for another scalar type ("scalar type 'short' is not supported"), for
// a non-finite value, and for field data delta/d0/scale/porosity that are not positive
// (porosity: in [0, 1]).
// Any scalar type from standard input too (one pass); more than 2^31 - 2 points (the most the
// labelling takes) are refused from the header of a file, before its data are read.
FlowImage read_vtk_image(const std::string& path);
FlowImage read_vtk_image(io::Input& input);

// Reads nx*ny*nz raw bytes (x fastest; non-zero = fluid) from path ("-" = stdin). Throws
// cmp::InputError(path, 0, "holds N bytes, --dims AxBxC needs M") when the size differs (a
// file's size is compared first; from a pipe memory grows as the bytes arrive).
FlowImage read_raw_image(const std::string& path, std::array<int, 3> dims);

}  // namespace cmp::flowrun
