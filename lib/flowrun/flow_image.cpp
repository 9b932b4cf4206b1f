#include "flowrun/flow_image.hpp"

#include "core/errors.hpp"
#include "io/input.hpp"
#include "io/parse_number.hpp"
#include "io/vtk.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <variant>

namespace cmp::flowrun {

namespace {

// The labelling of the pore space (voxel::label_components) numbers voxels in int32.
constexpr unsigned long long kMaxVoxels = 2147483646ULL;

template <io::VtkScalar T>
FlowImage from_vtk(const io::VoxelImage<T>& image, const std::string& path, long data_line) {
  FlowImage out;
  out.file = path;
  out.format = "vtk";
  out.dims = image.dims;
  out.origin = image.origin;
  out.spacing = image.spacing;
  out.fluid.resize(image.data.size());
  for (std::size_t i = 0; i < image.data.size(); ++i) {
    const T v = image.data[i];
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(v)) throw InputError(path, data_line, fmt::format("value {} of point {} is not finite", v, i));
    out.fluid[i] = v != T{} ? 1 : 0;
  }
  for (const auto& [name, value] : image.field_data) {
    const auto positive = [&](std::optional<double>& slot) {
      if (!(value > 0)) throw InputError(path, 0, fmt::format("field data {} = {} must be positive", name, value));
      slot = value;
    };
    if (name == "delta") positive(out.delta);
    else if (name == "d0" || name == "D0") positive(out.d0);
    else if (name == "scale") positive(out.scale);
    else if (name == "porosity") {
      if (!(value >= 0 && value <= 1))
        throw InputError(path, 0, fmt::format("field data porosity = {} must lie in [0, 1]", value));
      out.porosity = value;
    }
  }
  return out;
}

}  // namespace

long FlowImage::fluid_voxels() const { return static_cast<long>(std::count(fluid.begin(), fluid.end(), 1)); }

std::array<int, 3> parse_dims(const std::string& text) {
  std::array<int, 3> dims{0, 0, 0};
  const auto bad = [&] {
    return UsageError("--dims: expected NXxNYxNZ (three positive integers), e.g. 96x96x96, got '" + text + "'");
  };
  std::size_t at = 0;
  for (int a = 0; a < 3; ++a) {
    const auto x = a < 2 ? text.find('x', at) : text.size();
    if (x == std::string::npos) throw bad();
    long long v = 0;
    if (!io::try_parse_integer(text.substr(at, x - at), v) || v < 1 || v > (1LL << 31) - 1) throw bad();
    dims[a] = static_cast<int>(v);
    at = x + 1;
  }
  if (static_cast<unsigned long long>(dims[0]) * dims[1] * dims[2] > kMaxVoxels)
    throw UsageError("--dims: " + text + " makes 2^31 - 1 voxels or more, more than the labelling of the pore space "
                     "takes");
  return dims;
}

FlowImage read_vtk_image(io::Input& input) {
  const auto& path = input.path();
  // The header first, from a file: the labelling's limit is said before the data are read.
  std::optional<io::VtkInfo> info;
  if (path != "-") {
    info = io::read_vtk_info(path);
    if (info->size() > kMaxVoxels)
      throw InputError(path, 0, fmt::format("DIMENSIONS {} {} {} make 2^31 - 1 points or more, more than the labelling "
                                            "of the pore space takes", info->dims[0], info->dims[1], info->dims[2]));
  }
  auto image = std::visit(
      [&](const auto& im) {
        if (im.size() > kMaxVoxels)
          throw InputError(path, 0, fmt::format("DIMENSIONS {} {} {} make 2^31 - 1 points or more, more than the "
                                                "labelling of the pore space takes", im.dims[0], im.dims[1], im.dims[2]));
        return from_vtk(im, path, info ? info->data_line : 0);
      },
      io::read_vtk_any(input));
  if (info) image.title = info->title;
  return image;
}

FlowImage read_vtk_image(const std::string& path) {
  io::Input input(path);
  return read_vtk_image(input);
}

FlowImage read_raw_image(const std::string& path, std::array<int, 3> dims) {
  const unsigned long long want = static_cast<unsigned long long>(dims[0]) * dims[1] * dims[2];
  io::Input input(path);
  const auto name = fmt::format("{}x{}x{}", dims[0], dims[1], dims[2]);
  if (const auto left = input.bytes_left(); left && *left != want)
    throw InputError(path, 0, fmt::format("holds {} bytes, --dims {} needs {}", *left, name, want));
  FlowImage out;
  out.file = path;
  out.format = "raw";
  out.dims = dims;
  // From a pipe the image grows as the bytes arrive: 2 bytes for --dims 1000x1000x1000 are
  // refused without allocating a gigabyte first.
  auto& in = input.stream();
  constexpr unsigned long long kChunk = 1ULL << 24;
  unsigned long long got = 0;
  while (got < want) {
    const auto m = std::min(kChunk, want - got);
    out.fluid.resize(got + m);
    in.read(reinterpret_cast<char*>(out.fluid.data() + got), static_cast<std::streamsize>(m));
    const auto read = static_cast<unsigned long long>(in.gcount());
    got += read;
    if (read < m) break;
  }
  if (got < want) throw InputError(path, 0, fmt::format("holds {} bytes, --dims {} needs {}", got, name, want));
  if (in.peek() != std::char_traits<char>::eof())
    throw InputError(path, 0, fmt::format("holds more than the {} bytes --dims {} needs", want, name));
  for (auto& v : out.fluid) v = v != 0 ? 1 : 0;
  return out;
}

}  // namespace cmp::flowrun
