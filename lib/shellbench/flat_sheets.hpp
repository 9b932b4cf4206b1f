#pragma once
// Benchmarks on flat sheets:
//   B.5.2 (Fig. B.4B) Poisson ratio: a W x H rectangular sheet pulled apart by equal and
//     opposite uniform tractions on its left and right edges (a small strain, about 1e-3);
//     nu = -eps_y/eps_x (B.83 prints the inverse), eps_x from the mean x of the two loaded
//     edges, eps_y from the mean y of the top and bottom edges over the middle third.
//   B.5.3-B.5.4 (Figs. B.5-B.7) clamped circular plates: the rim and every vertex within one
//     lattice spacing of it fixed (w = 0 and, to that resolution, dw/dr = 0), a dead load along
//     -z: a point load P0 on the centre vertex, or a uniform pressure q spread over the vertices
//     by their dual areas. The deflection w = -z of every vertex.
#include "shell/relax.hpp"
#include "shell/shell_parameters.hpp"

#include <string>
#include <vector>

namespace cmp::shellbench {

struct PoissonRow {
  std::string model;
  double nu_input = 0, nu_measured = 0, strain_x = 0;
  shell::RelaxResult relax;
};
// One row per (model, nu): the sheet of side `side` with about `vertices` vertices.
std::vector<PoissonRow> poisson_ratios(const std::vector<std::string>& models, const std::vector<double>& nus,
                                       double side, long vertices, double youngs_modulus, double thickness,
                                       double relative_tolerance = 1e-9);

struct PlateLoad {
  bool point = true;  // a point load P0 [force] on the centre, else a uniform pressure q [pressure]
  double value = 0;
};

struct PlateCase {
  double radius = 2.25;                          // R0 [m]
  long vertices = 1200;                          // about this many
  shell::MaterialParameters material{25e6, 1.0 / 3.0, 0.1};
  std::string stretching = "svk";
  std::string bending = "hinge-uniform";         // "" for a membrane
  double relative_tolerance = 1e-8;
  long max_iterations = 2'000'000;
};

struct PlateResult {
  std::vector<double> r, w;  // every free vertex: distance from the centre, deflection (>0 along the load)
  double w_max = 0;          // deflection of the centre vertex
  shell::RelaxResult relax;
};

// Solves the loads in order, each from the previous state.
std::vector<PlateResult> clamped_plate(const PlateCase& c, const std::vector<PlateLoad>& loads);

}  // namespace cmp::shellbench
