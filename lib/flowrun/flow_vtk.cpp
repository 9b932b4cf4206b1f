#include "flowrun/flow_vtk.hpp"

#include "io/atomic_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace cmp::flowrun {

namespace {

// Appends v as a big-endian 32-bit float.
void put_float(std::string& buffer, double v) {
  const auto u = std::bit_cast<std::uint32_t>(static_cast<float>(v));
  const char b[4] = {static_cast<char>(u >> 24), static_cast<char>(u >> 16), static_cast<char>(u >> 8),
                     static_cast<char>(u)};
  buffer.append(b, 4);
}

void put_double(std::string& buffer, double v) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  for (int k = 7; k >= 0; --k) buffer.push_back(static_cast<char>(u >> (8 * k)));
}

constexpr std::size_t kChunk = 1 << 16;

}  // namespace

std::pair<Eigen::Vector3d, Eigen::Vector3d> refined_geometry(const Eigen::Vector3d& origin,
                                                             const Eigen::Vector3d& spacing, int M) {
  const Eigen::Vector3d h = spacing / M;
  return {origin - spacing / 2 + h / 2, h};
}

void write_flow_vtk(const std::string& path, const FlowField& field, const std::string& title) {
  const std::size_t n = static_cast<std::size_t>(field.dims[0]) * field.dims[1] * field.dims[2];
  if (field.velocity.size() != 3 * n || field.density.size() != n || field.fluid.size() != n)
    throw std::invalid_argument("write_flow_vtk: array sizes disagree with the dimensions");
  std::string t = title.substr(0, 255);
  std::replace(t.begin(), t.end(), '\n', ' ');
  std::replace(t.begin(), t.end(), '\r', ' ');
  io::AtomicOutput out(path);
  auto& s = out.stream();
  const auto& o = field.origin;
  const auto& h = field.spacing;
  s << fmt::format("# vtk DataFile Version 3.0\n{}\nBINARY\nDATASET STRUCTURED_POINTS\n"
                   "DIMENSIONS {} {} {}\nORIGIN {} {} {}\nSPACING {} {} {}\n",
                   t, field.dims[0], field.dims[1], field.dims[2], o[0], o[1], o[2], h[0], h[1], h[2]);
  std::string buffer;
  if (!field.field_data.empty()) {
    s << fmt::format("FIELD FieldData {}\n", field.field_data.size());
    for (const auto& [name, value] : field.field_data) {
      buffer.clear();
      put_double(buffer, value);
      s << name << " 1 1 double\n" << buffer << '\n';
    }
  }
  const auto write_chunks = [&](std::size_t count, const auto& put) {
    for (std::size_t start = 0; start < count; start += kChunk) {
      buffer.clear();
      for (std::size_t i = start; i < std::min(count, start + kChunk); ++i) put(i);
      s.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    }
    s << '\n';
  };
  s << fmt::format("POINT_DATA {}\nSCALARS density float 1\nLOOKUP_TABLE default\n", n);
  write_chunks(n, [&](std::size_t i) { put_float(buffer, field.fluid[i] ? field.density[i] : 0.0); });
  s << "VECTORS velocity float\n";
  write_chunks(3 * n, [&](std::size_t i) { put_float(buffer, field.fluid[i / 3] ? field.velocity[i] : 0.0); });
  s << "SCALARS fluid unsigned_char 1\nLOOKUP_TABLE default\n";
  write_chunks(n, [&](std::size_t i) { buffer.push_back(static_cast<char>(field.fluid[i])); });
  out.commit();
}

}  // namespace cmp::flowrun
