#include "io/vtk.hpp"

#include "core/errors.hpp"
#include "io/atomic_output.hpp"
#include "io/input.hpp"
#include "io/line_reader.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace cmp::io {

namespace {

constexpr std::size_t kChunk = 1 << 16;  // values per chunk when converting byte order

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Reverses the bytes of each value in place (the legacy format is big-endian).
template <class T>
void swap_bytes(T* values, std::size_t n) {
  if constexpr (sizeof(T) > 1 && std::endian::native == std::endian::little) {
    auto* bytes = reinterpret_cast<unsigned char*>(values);
    for (std::size_t i = 0; i < n; ++i)
      std::reverse(bytes + i * sizeof(T), bytes + (i + 1) * sizeof(T));
  }
}

// Tokens of the next non-blank line; at the end of the file, says what was expected.
const std::vector<std::string_view>& keyword_line(LineReader& in, const char* expected) {
  do {
    if (!in.next()) in.fail_end(std::string("expected ") + expected);
  } while (in.blank());
  return in.tokens();
}

Eigen::Vector3d three_numbers(LineReader& in, const std::vector<std::string_view>& t,
                              const char* what, bool positive) {
  if (t.size() != 4) in.fail(fmt::format("expected '{} x y z', got {} fields", t[0], t.size()));
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    v[i] = parse_double(t[i + 1], in.path(), in.line_number(), what);
    if (positive && !(v[i] > 0))
      in.fail(fmt::format("{} {} is not positive", what, quote_token(t[i + 1])));
  }
  return v;
}

constexpr unsigned long long kMaxPoints = 1ULL << 40;

// Size in bytes of a VTK legacy data type, 0 for one this reader does not know.
std::size_t vtk_type_size(const std::string& type) {
  if (type == "double" || type == "long" || type == "unsigned_long" || type == "vtkidtype" ||
      type == "vtktypeint64" || type == "vtktypeuint64")
    return 8;
  if (type == "float" || type == "int" || type == "unsigned_int") return 4;
  if (type == "short" || type == "unsigned_short") return 2;
  if (type == "char" || type == "unsigned_char" || type == "bit") return 1;
  return 0;
}

// One big-endian binary value of the given type as a double.
double decode_big_endian(const unsigned char* b, const std::string& type) {
  const auto size = vtk_type_size(type);
  std::uint64_t u = 0;
  for (std::size_t i = 0; i < size; ++i) u = (u << 8) | b[i];
  if (type == "double") return std::bit_cast<double>(u);
  if (type == "float") return std::bit_cast<float>(static_cast<std::uint32_t>(u));
  if (type == "int") return static_cast<std::int32_t>(u);
  if (type == "short") return static_cast<std::int16_t>(u);
  if (type == "char") return static_cast<std::int8_t>(u);
  if (type == "long" || type == "vtkidtype" || type == "vtktypeint64")
    return static_cast<double>(static_cast<std::int64_t>(u));
  return static_cast<double>(u);
}

// A FIELD block "FIELD name n" and its n arrays "name components tuples type" with their
// values; arrays of one value go into info.field_data, others are read and dropped.
void read_field(LineReader& in, const std::vector<std::string_view>& head, VtkInfo& info) {
  if (head.size() != 3) in.fail("expected 'FIELD name n' (n arrays)");
  const auto arrays =
      parse_integer(head[2], in.path(), in.line_number(), "the number of FIELD arrays", 0, 1 << 16);
  for (long long a = 0; a < arrays; ++a) {
    const auto t = keyword_line(in, "a FIELD array 'name components tuples type'");
    if (t.size() != 4)
      in.fail(fmt::format("expected a FIELD array 'name components tuples type', got {} fields",
                          t.size()));
    const std::string name(t[0]);
    const auto components =
        parse_integer(t[1], in.path(), in.line_number(), "the components of a FIELD array", 1, 1 << 20);
    const auto tuples = parse_integer(t[2], in.path(), in.line_number(),
                                      "the tuples of a FIELD array", 0, 1LL << 40);
    const auto type = lower(t[3]);
    const auto size = vtk_type_size(type);
    if (!size) in.fail("FIELD array type " + quote_token(t[3]) + " is not supported");
    const auto count = static_cast<unsigned long long>(components) * static_cast<unsigned long long>(tuples);
    double first = 0;
    if (info.binary) {
      const auto bytes = count * size;  // below 2^20 * 2^40 * 8 = 2^63
      if (const auto left = in.input().bytes_left(); left && bytes > *left)
        in.fail(fmt::format("unexpected end of file: FIELD array {} needs {} bytes, the file has {} "
                            "left",
                            quote_token(name), bytes, *left));
      unsigned char chunk[1 << 12];
      for (unsigned long long done = 0; done < bytes;) {
        const auto n = std::min<unsigned long long>(sizeof chunk, bytes - done);
        in.stream().read(reinterpret_cast<char*>(chunk), static_cast<std::streamsize>(n));
        if (static_cast<unsigned long long>(in.stream().gcount()) != n)
          in.fail(fmt::format("unexpected end of file in the values of FIELD array {}",
                              quote_token(name)));
        if (done == 0) first = decode_big_endian(chunk, type);
        if (done == 0 && !std::isfinite(first))
          in.fail(fmt::format("FIELD array {} holds {}: its values must be finite", quote_token(name), first));
        done += n;
      }
    } else {
      unsigned long long got = 0;
      while (got < count) {
        if (!in.next())
          in.fail_end(fmt::format("expected {} values of FIELD array {}", count, quote_token(name)));
        for (const auto token : in.tokens()) {
          if (got == count)
            in.fail(fmt::format("more than the {} values of FIELD array {}", count, quote_token(name)));
          const double v = parse_double(token, in.path(), in.line_number(), "a FIELD value");
          if (!std::isfinite(v))
            in.fail(fmt::format("FIELD array {} holds {}: its values must be finite", quote_token(name), token));
          if (got++ == 0) first = v;
        }
      }
    }
    if (count == 1) info.field_data.emplace_back(name, first);
  }
}

VtkInfo parse_header(LineReader& in) {
  VtkInfo info;
  if (!in.next()) in.fail_end("expected '# vtk DataFile Version x.x'");
  if (!in.line().starts_with("# vtk DataFile Version"))
    in.fail("not a VTK legacy file: expected '# vtk DataFile Version x.x' on the first line");
  if (!in.next()) in.fail_end("expected the title line");
  info.title = in.line();
  if (!in.next()) in.fail_end("expected ASCII or BINARY");
  const auto mode = in.tokens().size() == 1 ? lower(in.tokens()[0]) : std::string();
  if (mode != "ascii" && mode != "binary")
    in.fail("expected ASCII or BINARY on the third line, got " + quote_token(in.line()));
  info.binary = mode == "binary";

  auto t = keyword_line(in, "DATASET STRUCTURED_POINTS");
  if (lower(t[0]) != "dataset" || t.size() != 2)
    in.fail("expected 'DATASET STRUCTURED_POINTS', got " + quote_token(in.line()));
  if (lower(t[1]) != "structured_points")
    in.fail("dataset " + quote_token(t[1]) + " is not supported: expected STRUCTURED_POINTS");

  bool have_dims = false, have_origin = false, have_spacing = false;
  long spacing_line = 0;
  unsigned long long points = 0;
  while (true) {
    t = keyword_line(in, "POINT_DATA");
    const auto key = lower(t[0]);
    const auto once = [&](bool& seen) {
      if (seen) in.fail("second " + std::string(t[0]) + " line");
      seen = true;
    };
    if (key == "dimensions") {
      once(have_dims);
      if (t.size() != 4)
        in.fail(fmt::format("expected 'DIMENSIONS nx ny nz', got {} fields", t.size()));
      for (int i = 0; i < 3; ++i)
        info.dims[i] = static_cast<int>(
            parse_integer(t[i + 1], in.path(), in.line_number(), "a dimension", 1, INT_MAX));
      // The product in 128 bits: three dimensions below 2^31 can pass 2^64.
      const auto product = static_cast<unsigned __int128>(info.dims[0]) *
                           static_cast<unsigned>(info.dims[1]) * static_cast<unsigned>(info.dims[2]);
      if (product > kMaxPoints)
        in.fail(fmt::format("DIMENSIONS {} {} {} make more than 2^40 points (the most this "
                            "reader takes)",
                            info.dims[0], info.dims[1], info.dims[2]));
      points = static_cast<unsigned long long>(product);
    } else if (key == "origin") {
      once(have_origin);
      info.origin = three_numbers(in, t, "an origin coordinate", false);
    } else if (key == "spacing" || key == "aspect_ratio") {  // ASPECT_RATIO: VTK 1.0/2.0
      once(have_spacing);
      spacing_line = in.line_number();
      info.spacing = three_numbers(in, t, "a spacing", true);
    } else if (key == "field") {
      read_field(in, t, info);
    } else if (key == "point_data") {
      // The image's extent (and the areas made from the spacing, such as a permeability in
      // the file's units) must be finite numbers: SPACING 1e308 passes each value alone.
      for (int i = 0; have_spacing && i < 3; ++i) {
        const double extent = std::abs(info.origin[i]) + static_cast<double>(info.dims[i]) * info.spacing[i];
        if (!std::isfinite(extent) || !std::isfinite(info.spacing[i] * info.spacing[i]))
          throw InputError(in.path(), spacing_line,
                           fmt::format("SPACING {} with DIMENSIONS {} {} {}: the image's extent (or the spacing "
                                       "squared) overflows a double",
                                       info.spacing[i], info.dims[0], info.dims[1], info.dims[2]));
      }
      break;
    } else if (key == "cell_data") {
      in.fail("CELL_DATA is not supported: expected POINT_DATA (values on the grid points)");
    } else {
      in.fail("unexpected " + quote_token(t[0]) + " in a STRUCTURED_POINTS header");
    }
  }
  if (!have_dims) in.fail("POINT_DATA before DIMENSIONS");
  if (t.size() != 2) in.fail("expected 'POINT_DATA n'");
  const auto n = parse_integer(t[1], in.path(), in.line_number(), "the number of points", 0);
  if (static_cast<unsigned long long>(n) != points)
    in.fail(fmt::format("POINT_DATA {} disagrees with DIMENSIONS {} {} {} ({} points)", n,
                        info.dims[0], info.dims[1], info.dims[2], points));

  t = keyword_line(in, "SCALARS name type");
  if (lower(t[0]) != "scalars")
    in.fail("expected 'SCALARS name type' (one scalar field), got " + quote_token(t[0]));
  if (t.size() < 3 || t.size() > 4) in.fail("expected 'SCALARS name type [1]'");
  info.name = t[1];
  info.type = lower(t[2]);
  info.scalars_line = in.line_number();
  if (t.size() == 4 && t[3] != "1")
    in.fail("SCALARS with " + quote_token(t[3]) + " components: only 1 is supported");
  t = keyword_line(in, "LOOKUP_TABLE");
  if (lower(t[0]) != "lookup_table" || t.size() != 2)
    in.fail("expected 'LOOKUP_TABLE default' after SCALARS, got " + quote_token(in.line()));
  info.data_line = in.line_number() + 1;
  return info;
}

template <class T>
void read_ascii(LineReader& in, const VtkInfo& info, std::vector<T>& data) {
  const std::size_t n = info.size();
  const std::string what = "a value of type " + info.type;
  while (data.size() < n) {
    if (!in.next()) in.fail_end(fmt::format("expected {} values, got {}", n, data.size()));
    for (const auto token : in.tokens()) {
      if (data.size() == n) in.fail(fmt::format("more than the {} values of POINT_DATA", n));
      if constexpr (std::same_as<T, float>) {
        data.push_back(parse_float(token, in.path(), in.line_number(), what));
      } else if constexpr (std::same_as<T, double>) {
        data.push_back(parse_double(token, in.path(), in.line_number(), what));
      } else {
        constexpr long long lo = std::same_as<T, std::uint8_t> ? 0 : INT_MIN;
        constexpr long long hi = std::same_as<T, std::uint8_t> ? 255 : INT_MAX;
        data.push_back(
            static_cast<T>(parse_integer(token, in.path(), in.line_number(), what, lo, hi)));
      }
    }
  }
  while (in.next())
    if (!in.blank()) in.fail(fmt::format("more than the {} values of POINT_DATA", n));
}

template <class T>
void read_binary(LineReader& in, const VtkInfo& info, std::vector<T>& data) {
  const std::size_t n = info.size();  // below 2^40 (parse_header)
  const std::uint64_t bytes = static_cast<std::uint64_t>(n) * sizeof(T);
  auto& stream = in.stream();
  const auto truncated = [&](std::uint64_t got) {
    throw InputError(in.path(), info.data_line,
                     fmt::format("unexpected end of file: expected {} values of {} ({} bytes), "
                                 "got {} bytes",
                                 n, info.type, bytes, got));
  };
  // A regular file too short for the dimensions is refused before anything is allocated; from
  // a pipe or a FIFO the image grows as the bytes arrive.
  const auto left = in.input().bytes_left();
  if (left && *left < bytes) truncated(*left);
  constexpr std::size_t kChunkValues = std::size_t{1} << 20;
  std::size_t got = 0;
  if (left) data.resize(n);
  while (got < n) {
    const std::size_t m = std::min(kChunkValues, n - got);
    if (data.size() < got + m) data.resize(got + m);
    stream.read(reinterpret_cast<char*>(data.data() + got), static_cast<std::streamsize>(m * sizeof(T)));
    const auto read = static_cast<std::size_t>(stream.gcount());
    if (read != m * sizeof(T)) truncated(got * sizeof(T) + read);
    got += m;
  }
  swap_bytes(data.data(), n);
  // Only whitespace (usually one newline) may follow: a second field would go unread.
  char c;
  while (stream.get(c))
    if (!std::isspace(static_cast<unsigned char>(c)))
      throw InputError(in.path(), 0,
                       fmt::format("unexpected content after the {} values (only "
                                   "one SCALARS field is supported)",
                                   n));
}

template <class T>
void check_image(const VoxelImage<T>& image) {
  for (int d : image.dims)
    if (d < 1) throw std::invalid_argument("write_vtk: every dimension must be at least 1");
  if (image.data.size() != image.size())
    throw std::invalid_argument(fmt::format("write_vtk: {} values for a {}x{}x{} image",
                                            image.data.size(), image.dims[0], image.dims[1],
                                            image.dims[2]));
  if (!image.origin.allFinite()) throw std::invalid_argument("write_vtk: origin not finite");
  for (int i = 0; i < 3; ++i)
    if (!(image.spacing[i] > 0) || !std::isfinite(image.spacing[i]))
      throw std::invalid_argument("write_vtk: spacing must be positive and finite");
  if (image.name.empty() || image.name.find_first_of(" \t\r\n\v\f") != std::string::npos)
    throw std::invalid_argument("write_vtk: scalar name '" + image.name +
                                "' is empty or holds whitespace");
  for (const auto& [name, value] : image.field_data) {
    if (name.empty() || name.find_first_of(" \t\r\n\v\f") != std::string::npos)
      throw std::invalid_argument("write_vtk: field data name '" + name +
                                  "' is empty or holds whitespace");
    if (!std::isfinite(value))  // a computed quantity went wrong: the run fails, exit 1
      throw ComputationError(fmt::format("field data '{}' of the VTK image became {}: a result file holds finite "
                                         "numbers only", name, value));
  }
}

}  // namespace

// The values after a header parse_header has read.
template <class T>
VoxelImage<T> read_body(LineReader& in, const VtkInfo& info) {
  VoxelImage<T> image;
  image.dims = info.dims;
  image.origin = info.origin;
  image.spacing = info.spacing;
  image.name = info.name;
  image.field_data = info.field_data;
  if (info.binary)
    read_binary(in, info, image.data);
  else
    read_ascii(in, info, image.data);
  return image;
}

VtkInfo read_vtk_info(const std::string& path) {
  LineReader in(path);
  return parse_header(in);
}

template <VtkScalar T>
VoxelImage<T> read_vtk(const std::string& path) {
  Input input(path);
  return read_vtk<T>(input);
}

template <VtkScalar T>
VoxelImage<T> read_vtk(Input& input) {
  LineReader in(input);
  const auto& path = in.path();
  const auto info = parse_header(in);
  if (info.type != vtk_type_name<T>())
    throw InputError(
        path, info.scalars_line,
        fmt::format("scalar type is '{}', expected '{}'", info.type, vtk_type_name<T>()));
  return read_body<T>(in, info);
}

AnyVoxelImage read_vtk_any(Input& input) {
  LineReader in(input);
  const auto info = parse_header(in);
  if (info.type == "unsigned_char") return read_body<std::uint8_t>(in, info);
  if (info.type == "int") return read_body<std::int32_t>(in, info);
  if (info.type == "float") return read_body<float>(in, info);
  if (info.type == "double") return read_body<double>(in, info);
  throw InputError(in.path(), info.scalars_line,
                   fmt::format("scalar type '{}' is not supported: expected unsigned_char, int, float or double",
                               info.type));
}

template <VtkScalar T>
void write_vtk(std::ostream& out, const VoxelImage<T>& image, const std::string& title) {
  check_image(image);
  std::string t = title.substr(0, 255);
  std::replace(t.begin(), t.end(), '\n', ' ');
  std::replace(t.begin(), t.end(), '\r', ' ');
  const auto& o = image.origin;
  const auto& s = image.spacing;
  out << fmt::format(
      "# vtk DataFile Version 3.0\n{}\nBINARY\nDATASET STRUCTURED_POINTS\n"
      "DIMENSIONS {} {} {}\nORIGIN {} {} {}\nSPACING {} {} {}\n",
      t, image.dims[0], image.dims[1], image.dims[2], o[0], o[1], o[2], s[0], s[1], s[2]);
  if (!image.field_data.empty()) {
    // Dataset-level field data, as vtkDataWriter writes it: one 1x1 double array per value,
    // the value in big-endian binary followed by a line break.
    out << fmt::format("FIELD FieldData {}\n", image.field_data.size());
    for (const auto& [name, value] : image.field_data) {
      out << name << " 1 1 double\n";
      double v = value;
      swap_bytes(&v, 1);
      out.write(reinterpret_cast<const char*>(&v), sizeof v);
      out << '\n';
    }
  }
  out << fmt::format("POINT_DATA {}\nSCALARS {} {} 1\nLOOKUP_TABLE default\n", image.size(),
                     image.name, vtk_type_name<T>());
  std::vector<T> chunk(std::min(kChunk, image.data.size()));
  for (std::size_t start = 0; start < image.data.size(); start += kChunk) {
    const std::size_t n = std::min(kChunk, image.data.size() - start);
    std::copy_n(image.data.begin() + static_cast<std::ptrdiff_t>(start), n, chunk.begin());
    swap_bytes(chunk.data(), n);
    out.write(reinterpret_cast<const char*>(chunk.data()),
              static_cast<std::streamsize>(n * sizeof(T)));
  }
  out << '\n';  // readers such as meshio expect a line break after the binary block
}

template <VtkScalar T>
void write_vtk(const std::string& path, const VoxelImage<T>& image, const std::string& title) {
  check_image(image);
  AtomicOutput out(path);
  write_vtk(out.stream(), image, title);
  out.commit();
}

#define CMP_VTK_INSTANTIATE(T)                                                         \
  template VoxelImage<T> read_vtk<T>(const std::string&);                              \
  template VoxelImage<T> read_vtk<T>(Input&);                                          \
  template void write_vtk<T>(std::ostream&, const VoxelImage<T>&, const std::string&); \
  template void write_vtk<T>(const std::string&, const VoxelImage<T>&, const std::string&);
CMP_VTK_INSTANTIATE(std::uint8_t)
CMP_VTK_INSTANTIATE(std::int32_t)
CMP_VTK_INSTANTIATE(float)
CMP_VTK_INSTANTIATE(double)
#undef CMP_VTK_INSTANTIATE

}  // namespace cmp::io
