#include "spheres/sphere_packing.hpp"

#include "core/errors.hpp"
#include "io/xyz.hpp"
#include "io/xyz_frame.hpp"
#include "neighbours/box.hpp"
#include "neighbours/cell_grid.hpp"

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

SpherePacking frame_to_packing(const io::XyzFrame& frame) {
  if (!frame.has_lattice) frame.fail("no Lattice: a sphere packing needs its periodic box");
  const Eigen::Matrix3d& a = frame.lattice;
  if (a(0, 1) != 0 || a(0, 2) != 0 || a(1, 0) != 0 || a(1, 2) != 0 || a(2, 0) != 0 || a(2, 1) != 0)
    frame.fail("the Lattice is not an orthorhombic box (off-diagonal entries are not zero)");
  if (!(a(0, 0) > 0 && a(1, 1) > 0 && a(2, 2) > 0)) frame.fail("the Lattice has a non-positive side");
  if (!(frame.pbc[0] && frame.pbc[1] && frame.pbc[2])) frame.fail("pbc is not \"T T T\": a periodic packing is needed");
  if (!frame.find("radius")) frame.fail("no radius column (Properties=...:radius:R:1)");
  SpherePacking p;
  p.box = a.diagonal();
  p.positions = frame.positions();
  p.radii = frame.real_column("radius").col(0);
  const long first_atom_line = frame.line + 2;
  for (int i = 0; i < p.size(); ++i)
    if (!(p.radii[i] > 0) || !std::isfinite(p.radii[i]))
      throw InputError(frame.file, first_atom_line + i, "radius must be a positive number");
  // Duplicated particles: centres (nearly) on top of each other.
  if (p.size() > 1) {
    neighbours::Box box;
    box.lengths = p.box;
    box.periodic = {true, true, true};
    // Cells about a radius wide: few points per cell, and a duplicate is always in reach.
    const double cutoff = std::min(p.radii.minCoeff(), p.box.minCoeff() / 2);
    neighbours::CellGrid grid(box, cutoff);
    grid.build(p.positions);
    long first = -1;  // the earliest particle in the file that repeats an earlier one
    grid.for_each_pair(p.positions, [&](int i, int j, const Eigen::Vector3d&, double r2) {
      if (std::sqrt(r2) < 1e-9 * (p.radii[i] + p.radii[j])) {
        const long later = std::max(i, j);
        if (first < 0 || later < first) first = later;
      }
    });
    if (first >= 0)
      throw InputError(frame.file, first_atom_line + first,
                       "particle duplicates another one (centres closer than 1e-9 of their radii)");
  }
  return p;
}

std::vector<SpherePacking> read_sphere_packings(const std::string& path) {
  std::vector<SpherePacking> packings;
  for (const auto& frame : io::read_xyz(path)) packings.push_back(frame_to_packing(frame));
  return packings;
}

}  // namespace cmp::spheres
