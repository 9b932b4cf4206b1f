#pragma once
// Pore lattices of periodic sphere arrangements with exact wall distances: the simple cubic
// array of the drag benchmarks and, from a packing, the geometry for interpolated bounce-back.
#include "lbm/pore_lattice.hpp"

#include <cstdint>
#include <span>
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

// The bench's porous box: random overlapping spheres of radius n/12 in an n^3 periodic
// lattice (centres uniform, 16 at a time from xoshiro seeded with `seed`) until the porosity
// falls below `target_porosity` in (0, 1); staircase walls (no wall_fraction). The same
// arguments give the same lattice node for node, so two codes can be timed on it.
PoreLattice random_sphere_box(int n, double target_porosity, std::uint64_t seed);

// Stokes drag of the simple cubic array: K = F / (6 pi mu a U) per sphere, U the superficial
// velocity, F = |grad p| L^3 (the pressure gradient times the cell volume).
struct DragReference {
  double solid_fraction;
  double K;
};

// Zick & Homsy (1982), J. Fluid Mech. 115, 13, Table 2, simple cubic array, c = 0.027 to
// 0.5236 (touching), as tabulated in the Basilisk test src/test/spheres.c.
std::span<const DragReference> zick_homsy_simple_cubic();

// Hasimoto's (1959) dilute series as extended by Sangani & Acrivos (1982) for the simple
// cubic array: 1/K = 1 - 1.7601 c^(1/3) + c - 1.5593 c^2 + 3.9799 c^(8/3) - 3.0734 c^(10/3).
double hasimoto_drag(double solid_fraction);

// The permeability, in lattice units, of the array of spheres of solid fraction c in n^3
// periodic cells with drag K: kappa = n^3 / (6 pi a K), a = n (3c / (4 pi))^(1/3).
double sphere_array_kappa(int n, double solid_fraction, double K);

}  // namespace cmp::lbm
