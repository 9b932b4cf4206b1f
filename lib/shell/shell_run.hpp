#pragma once
// The protocol of `shellpack shell`: one shell (or several) inflated in load steps to a turgor
// Pi, then, with walls, squeezed between two parallel plates in steps; a full relaxation
// after every step and one table row of observables per step.
//   stage "inflate": Pi = P k/n for k = 1..n (--pressure P --steps n)
//   stage "squeeze": plates at z_c -+ g/2, g = D (1 - S k/m) for k = 0..m (--walls D
//                    --squeeze S --squeeze-steps m), z_c the centre of the mesh's bounding box;
//                    with the "volume" pressure the targets are the inflated volumes.
// A step that folds elements over (folded_hinges) or makes a force non-finite stops the run
// with cmp::ComputationError saying at which step.
#include "shell/observables.hpp"
#include "shell/relax.hpp"
#include "shell/shell_model.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace cmp::shell {

struct ShellRunOptions {
  ShellModel model;            // model.pressure: "turgor" or "volume"; model.load is ignored
  double pressure = 0;         // final turgor P [pressure]
  int pressure_steps = 1;      // n
  std::optional<double> wall_gap;  // D [length]: plates this far apart, or none
  double squeeze = 0;          // S in [0, 1): final gap D (1 - S)
  int squeeze_steps = 1;       // m
  RelaxParameters relax;       // relax.force_scale is set from the mesh
};

// Refuses, before any work, a mesh a pressurised shell cannot be: not a closed manifold, a
// vertex in no face, inconsistently oriented, inward-oriented, a degenerate triangle.
// Throws cmp::InputError(path, 0, what).
void check_closed_shell_mesh(const mesh::TriMesh& m, const std::string& path);

// Throws cmp::UsageError when the plates of gap D (at the bounding box's centre) would cut the
// mesh: a vertex sphere (radius R_v) reaches past a plate.
void check_walls_clear(const mesh::TriMesh& m, double gap, double vertex_radius);

// The two plates of gap g around height z_c, normals facing each other.
std::vector<Plane> plates(double z_centre, double gap);

struct ShellRunRow {
  int step = 0;
  std::string stage;           // "inflate" or "squeeze"
  double applied_pressure = 0; // the turgor asked for (constant volume: the inflation's P)
  double gap = 0;              // plate gap [length] (0 without walls)
  Observables observables;
  RelaxResult relax;
};

struct ShellRunResult {
  std::vector<ShellRunRow> rows;
  std::vector<std::string> term_names;
  Eigen::VectorXd final_state;
};

// Runs the protocol; on_row(row) after every step (progress, messages). Throws as above.
ShellRunResult run_shell(const mesh::TriMesh& rest, const ShellRunOptions& o,
                         const std::function<void(const ShellRunRow&)>& on_row = {},
                         const RelaxProgress& progress = {});

// The CSV of a run (docs/formats.md): provenance and parameters as "# key=value", one row per
// step, units as suffixes explained in "# units=".
void write_shell_table(std::ostream& out, const ShellRunResult& r, const ShellRunOptions& o,
                       const std::string& provenance);

}  // namespace cmp::shell
