#pragma once
// Which lattice nodes are fluid: the geometry a FlowSolver runs on.
#include <cstdint>
#include <functional>
#include <vector>

namespace cmp::lbm {

struct PoreLattice {
  int nx = 0, ny = 0, nz = 0;       // nodes per axis
  std::vector<std::uint8_t> fluid;  // nx*ny*nz, x fastest: i = x + nx*(y + ny*z); non-zero = fluid
  // Optional exact wall distances for interpolated bounce-back (Bouzidi et al. 2001, linear):
  // for fluid node (x, y, z) and D3Q19 direction q (lbm/d3q19.hpp) whose neighbour is solid,
  // the fraction in (0, 1] of the link that lies in fluid (0.5 = the half-way wall of plain
  // bounce-back). Called once per wall link when the solver is built, with the neighbour's
  // coordinates wrapped periodically. Empty = half-way bounce-back everywhere.
  std::function<double(int x, int y, int z, int q)> wall_fraction;

  // Index of node (x, y, z) in `fluid`.
  long index(int x, int y, int z) const { return x + static_cast<long>(nx) * (y + static_cast<long>(ny) * z); }
  // Number of nodes nx*ny*nz.
  long nodes() const { return static_cast<long>(nx) * ny * nz; }
  // Number of fluid nodes.
  long fluid_count() const;
  // Fluid nodes / all nodes.
  double porosity() const;
};

// An all-fluid box (the speed benchmark's dense case).
PoreLattice open_box(int nx, int ny, int nz);

// A channel along `axis`: plane Poiseuille between two solid walls (one node layer each) at
// the ends of `wall_axis`, `width` fluid nodes between them; the third axis is periodic.
// With duct = true, walls also close the third axis (a square or rectangular duct of
// width x width2 fluid nodes).
PoreLattice channel(int length, int width, int axis, int wall_axis, bool duct = false, int width2 = 0);

}  // namespace cmp::lbm
