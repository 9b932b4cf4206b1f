#pragma once
// A packing of elastic shells built from a jammed sphere packing (thesis 5.2.1 and 5.5.1: the
// sphere centres "replaced by the Finite Element representation"): one copy of a closed
// outward-oriented cell mesh per sphere, scaled with the sphere's radius, centred on it and
// turned by a random rotation, all in one mesh (shell after shell) in the sphere packing's box.
//
// Units: lengths in D_0, the volume-equivalent diameter (6 V / pi)^(1/3) of the mean shell
// inflated at Pi_0. Shells touch when their mid-surfaces come within the contact reach (2 R_v
// for vertex spheres, delta for hertz-faces), so a shell's contact envelope is about D + reach
// across: the packing is scaled so that the mean sphere diameter becomes D_0 + reach (the
// `envelope` argument, reach / D_0), and the start is the jammed packing of the envelopes. Shell i gets r_i / <r> times the rest diameter (the compress
// driver picks the rest diameter whose inflated shell at Pi_0 has diameter D_0, see
// rest_diameter_for_inflated).
#include "io/sphere_packing_xyz.hpp"
#include "mesh/tri_mesh.hpp"
#include "shell/relax.hpp"
#include "shell/shell_model.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cmp::shell {

struct ShellPacking {
  mesh::TriMesh mesh;                   // every shell, shell after shell [D_0]
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  // box sides [D_0]
  std::array<bool, 3> periodic{true, true, true};
  std::vector<int> shell_vertex_counts;  // one per shell (each the template's count)
  std::vector<double> size_factors;      // r_i / <r> of each shell's sphere
};

// The first frame of an extended XYZ sphere packing (`shellpack jam`), checked for a start of
// shells: a periodic Lattice on every axis, and no two centres closer than half their summed
// radii (overlapping duplicates). Throws cmp::InputError naming the file and line.
io::SpherePackingFrame read_start_packing(const std::string& path);

// The cell template: `m` checked as a closed, consistently outward-oriented, non-degenerate
// single shell (cmp::InputError(path, 0, ...) otherwise), moved so its vertex centroid is at
// the origin and scaled to volume-equivalent diameter 1.
mesh::TriMesh normalised_cell(const mesh::TriMesh& m, const std::string& path);

// The packing: shell i = template (normalised_cell) scaled by rest_diameter r_i / <r>, turned
// by a rotation drawn uniformly (Shoemake's quaternions, Random(seed, i)) and centred on
// sphere i's centre times (1 + envelope) / (2 <r>); box = Lattice (1 + envelope) / (2 <r>).
ShellPacking place_shells(const io::SpherePackingFrame& spheres, const mesh::TriMesh& cell, double rest_diameter,
                          double envelope, std::uint64_t seed);

// The rest diameter (volume-equivalent, in D_0) of the normalised template whose shell,
// inflated alone at the model's turgor (model.load.turgor, the "turgor" pressure style; model's
// stretching, bending and material), has volume-equivalent diameter 1: three fixed-point
// steps d <- d / D_inflated (the strain depends weakly on d at a fixed thickness). FIRE's
// iteration cap is raised to at least 10^6 here (one shell; the cap is meant for the packing).
double rest_diameter_for_inflated(const mesh::TriMesh& cell, const ShellModel& model, const RelaxParameters& relax);

// The largest circumradius of the template's triangles (normalised_cell: diameter 1).
double max_circumradius(const mesh::TriMesh& cell);

}  // namespace cmp::shell
