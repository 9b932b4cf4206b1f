#include "readers.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/input.hpp"
#include "io/off.hpp"
#include "io/sphere_packing_xyz.hpp"
#include "io/vtk.hpp"
#include "io/xyz.hpp"
#include "packing/packing_file.hpp"

#include <climits>
#include <sstream>
#include <stdexcept>

namespace cmp::fuzz {

namespace {

// Runs read on an Input over bytes.
template <class Read>
void with_input(const std::string& bytes, Read&& read) {
  std::istringstream stream(bytes);
  io::Input input("fuzz", stream);
  read(input);
}

// f(), with a cmp::InputError taken as a correct answer (used for the calls after a first
// read succeeded, so one bad cell does not hide the others).
template <class F>
void tolerate_input_error(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

void read_off(const std::string& bytes) {
  with_input(bytes, [](io::Input& in) {
    const auto off = io::read_off(in);
    (void)io::shell_vertex_offsets(off.packing);
  });
}

void read_xyz(const std::string& bytes) {
  with_input(bytes, [](io::Input& in) {
    for (const auto& frame : io::read_xyz(in)) {
      tolerate_input_error([&] { (void)frame.positions(); });
      tolerate_input_error([&] { (void)io::sphere_packing_from_frame(frame, io::PbcRule::as_in_file); });
    }
  });
}

void read_csv(const std::string& bytes) {
  with_input(bytes, [](io::Input& in) {
    const auto t = io::read_csv(in);
    for (std::size_t r = 0; r < t.rows.size() && r < 64; ++r)
      for (int c = 0; c < static_cast<int>(t.header.size()) && c < 64; ++c) {
        tolerate_input_error([&] { (void)t.number(r, c); });
        tolerate_input_error([&] { (void)t.integer(r, c, INT_MIN, INT_MAX); });
      }
    tolerate_input_error([&] { (void)t.column("particles"); });
  });
}

void read_vtk(const std::string& bytes) {
  // The header tells the scalar type; each type is its own path through the reader.
  std::string type;
  try {
    with_input(bytes, [](io::Input& in) { (void)io::read_vtk<std::uint8_t>(in); });
    return;
  } catch (const InputError& e) {
    type = e.what();
  }
  if (type.find("scalar type is 'float'") != std::string::npos)
    with_input(bytes, [](io::Input& in) { (void)io::read_vtk<float>(in); });
  else if (type.find("scalar type is 'double'") != std::string::npos)
    with_input(bytes, [](io::Input& in) { (void)io::read_vtk<double>(in); });
  else if (type.find("scalar type is 'int'") != std::string::npos)
    with_input(bytes, [](io::Input& in) { (void)io::read_vtk<std::int32_t>(in); });
  else
    throw InputError("fuzz", 0, type);
}

void read_packing(const std::string& bytes) {
  with_input(bytes, [](io::Input& in) {
    packing::PackingReadOptions options;
    options.scale = 1.1;
    (void)packing::read_packings(in, options);
  });
  with_input(bytes, [](io::Input& in) {
    if (in.format() == io::InputFormat::xyz) (void)io::read_sphere_packing_xyz(in, io::PbcRule::require_all);
  });
}

}  // namespace

const std::vector<Reader>& readers() {
  static const std::vector<Reader> all{
      {"off", read_off}, {"xyz", read_xyz}, {"csv", read_csv}, {"vtk", read_vtk}, {"packing", read_packing}};
  return all;
}

const Reader& reader(std::string_view name) {
  for (const auto& r : readers())
    if (name == r.name) return r;
  throw std::invalid_argument("no reader '" + std::string(name) + "'");
}

}  // namespace cmp::fuzz
