#include "spheres/sphere_packing.hpp"

#include "core/errors.hpp"
#include "io/sphere_packing_xyz.hpp"
#include "io/xyz_frame.hpp"
#include "neighbours/box.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cmp::spheres {

double SpherePacking::volume_fraction() const {
  return 4.0 / 3.0 * std::numbers::pi * radii.array().cube().sum() / box_volume();
}

io::XyzFrame packing_to_frame(const SpherePacking& p) {
  io::XyzFrame frame;
  frame.lattice = p.box.asDiagonal();
  frame.has_lattice = true;
  frame.pbc = {true, true, true};
  neighbours::Box box;
  box.lengths = p.box;
  box.periodic = {true, true, true};
  mesh::VertexMatrix wrapped(p.size(), 3);
  for (int i = 0; i < p.size(); ++i) wrapped.row(i) = box.wrap(p.positions.row(i).transpose()).transpose();
  frame.set_species(std::vector<std::string>(static_cast<std::size_t>(p.size()), "X"));
  frame.set_positions(wrapped);
  frame.set_real_column("radius", p.radii);
  return frame;
}

namespace {
SpherePacking from_io(io::SpherePackingFrame&& f) {
  SpherePacking p;
  p.box = f.box;
  p.positions = std::move(f.centres);
  p.radii = std::move(f.radii);
  return p;
}
}  // namespace

SpherePacking frame_to_packing(const io::XyzFrame& frame) {
  return from_io(io::sphere_packing_from_frame(frame, io::PbcRule::require_all));
}

std::vector<SpherePacking> read_sphere_packings(const std::string& path) {
  std::vector<SpherePacking> packings;
  for (auto& f : io::read_sphere_packing_xyz(path, io::PbcRule::require_all))
    packings.push_back(from_io(std::move(f)));
  return packings;
}

}  // namespace cmp::spheres
