#pragma once
// Pore lattices of periodic sphere arrangements with exact wall distances: the simple cubic
// array of the drag benchmarks and, from a packing, the geometry for interpolated bounce-back.
#include "lbm/pore_lattice.hpp"

#include <vector>

namespace cmp::lbm {

struct LatticeSphere {
  double x, y, z;  // centre in node coordinates (node (i, j, k) sits at (i, j, k))
  double r;        // radius in node spacings
};

// An nx x ny x nz periodic lattice; a node is solid when it lies strictly inside a sphere
// (minimum image). wall_fraction: for a fluid node and a direction whose neighbour is solid,
// the exact fraction of the link up to the first sphere surface it crosses (clamped to
// [1e-6, 1]).
PoreLattice periodic_spheres(int nx, int ny, int nz, const std::vector<LatticeSphere>& spheres);

// One sphere of solid fraction c = 4 pi r^3 / (3 n^3) centred in an n^3 periodic box: the
// simple cubic array. radius = n (3c / (4 pi))^(1/3).
PoreLattice simple_cubic_array(int n, double solid_fraction);

}  // namespace cmp::lbm
