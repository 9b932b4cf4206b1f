#pragma once
// A packing of spheres in a periodic orthorhombic box: what `shellpack jam` makes and
// `shellpack structure`, percolate and the shell packings read.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cmp::io {
struct XyzFrame;
}

namespace cmp::spheres {

struct SpherePacking {
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  // side lengths of the periodic box [0, L)
  mesh::VertexMatrix positions;                   // #N by 3 centres
  Eigen::VectorXd radii;                          // #N radii

  int size() const { return static_cast<int>(positions.rows()); }
  double box_volume() const { return box.prod(); }
  // Sum of the sphere volumes over the box volume (overlaps counted twice, as usual).
  double volume_fraction() const;
  double mean_diameter() const { return size() ? 2 * radii.mean() : 0.0; }
};

// The packing as one extended XYZ frame: Lattice (diagonal), pbc="T T T", species X,
// pos (wrapped into the box) and radius; callers add info pairs and columns.
// Reading (frame_to_packing) applies the rules of io/sphere_packing_xyz.hpp with
// PbcRule::require_all: a diagonal Lattice, periodic flags on every axis, a radius column
// (radius, OVITO's Radius or ASE's radii) with positive radii, no duplicated particle, at
// least one sphere; each problem is a cmp::InputError naming file and line.
io::XyzFrame packing_to_frame(const SpherePacking& packing);
SpherePacking frame_to_packing(const io::XyzFrame& frame);
// Every frame of an extended XYZ file ("-" = stdin) as packings (throws as frame_to_packing /
// read_xyz).
std::vector<SpherePacking> read_sphere_packings(const std::string& path);

}  // namespace cmp::spheres
