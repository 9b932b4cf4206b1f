#include "flowrun/flow_image.hpp"

#include "core/errors.hpp"
#include "io/input.hpp"
#include "io/parse_number.hpp"
#include "io/vtk.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace cmp::flowrun {

namespace {

constexpr unsigned long long kMaxVoxels = 1ULL << 40;

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
    throw UsageError("--dims: " + text + " makes more than 2^40 voxels");
  return dims;
}

FlowImage read_vtk_image(const std::string& path) {
  if (path == "-") {  // one pass only: percolate's type
    io::Input input(path);
    return from_vtk(io::read_vtk<std::uint8_t>(input), path, 0);
  }
  const auto info = io::read_vtk_info(path);
  const auto titled = [&](FlowImage f) {
    f.title = info.title;
    return f;
  };
  if (info.type == "unsigned_char") return titled(from_vtk(io::read_vtk<std::uint8_t>(path), path, info.data_line));
  if (info.type == "int") return titled(from_vtk(io::read_vtk<std::int32_t>(path), path, info.data_line));
  if (info.type == "float") return titled(from_vtk(io::read_vtk<float>(path), path, info.data_line));
  if (info.type == "double") return titled(from_vtk(io::read_vtk<double>(path), path, info.data_line));
  throw InputError(path, info.scalars_line,
                   fmt::format("scalar type '{}' is not supported: expected unsigned_char, int, float or double",
                               info.type));
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
  out.fluid.resize(want);
  auto& in = input.stream();
  in.read(reinterpret_cast<char*>(out.fluid.data()), static_cast<std::streamsize>(want));
  const auto got = static_cast<unsigned long long>(in.gcount());
  if (got < want) throw InputError(path, 0, fmt::format("holds {} bytes, --dims {} needs {}", got, name, want));
  if (in.peek() != std::char_traits<char>::eof())
    throw InputError(path, 0, fmt::format("holds more than the {} bytes --dims {} needs", want, name));
  for (auto& v : out.fluid) v = v != 0 ? 1 : 0;
  return out;
}

}  // namespace cmp::flowrun
