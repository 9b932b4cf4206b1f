#pragma once
// `shellpack compress`'s job around the protocol of lib/shell/compression (periodic, or the
// rigid box with run.walls: then compress.csv adds wall_pressure_E, coverage and their ratio,
// and the packing OFFs say `# periodic 0 0 0` and walls=): the inputs read and
// checked before any work (a periodic jammed sphere packing, a closed outward cell mesh, the
// targets above the starting phi), the shells built and inflated, then box steps until the last
// target phi, with
//   - one packing OFF per target (-o with {phi}; docs/formats.md, the `# key=value` lines);
//   - after every step, a check that no shell passes through another (shell/penetration.hpp);
//   - compress.csv, one row per box step, written at the end (atomically);
//   - a progress bar (phi, step, residual) on a terminal;
//   - a checkpoint (io/checkpoint_file.hpp) every checkpoint_every seconds and at the end, from
//     which `--resume` continues to the same bytes as an uninterrupted run.
// A relaxation that stops unconverged saves the checkpoint of the last converged step and
// throws cmp::ComputationError (exit 1) with its residual.
#include "shell/compression.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cmp::packrun {

struct CompressJob {
  std::string packing_path;        // extended XYZ of `shellpack jam` (first frame)
  std::string mesh_path;           // the cell: closed outward triangle mesh (OFF)
  std::string output_pattern;      // packing OFF per target, {phi} replaced ("" none)
  std::string csv = "-";           // the table ('-' stdout, "" none)
  std::string checkpoint;          // "" none
  double checkpoint_every = 300;   // seconds
  std::string resume;              // continue from this checkpoint ("" a new run)
  std::vector<std::string> checkpoint_args;  // what the checkpoint records of the command line
  long stop_after_steps = 0;       // stop (checkpoint, table so far) after this many box steps of this process; 0 never
  std::uint64_t seed = 1;          // rotations of the shells
  double vertex_radius = 0;        // R_v [D_0]; 0: default_vertex_radius
  double contact_distance = 0;     // hertz-faces: delta [D_0]; 0: the thickness t
  bool check_penetration = true;   // point-in-mesh check after every step
  bool timings = false;            // `seconds` column
  bool quiet = false;
  shell::CompressionOptions run;   // model (material in units of E, t in D_0, shell_contact_style), Pi_0, step, targets, relax
};

// "a:b:c" (start:stop:step, inclusive) or "a,b,..." as ascending targets in (0, 1], each
// rounded to 12 significant digits. Throws cmp::UsageError (without the option's name).
std::vector<double> parse_phi_targets(const std::string& text);

// The default vertex radius: the thickness t (the thesis's R_v = t), raised to 0.75 times the
// largest circumradius of a shell's triangles (inflated size, largest shell) when the mesh is
// coarse, so that 2 R_v exceeds the distance from a triangle's corners to its circumcentre by
// 50 %: a vertex cannot slip through another shell's triangle while the Hertz overlap stays
// below a third of 2 R_v (measured: 16 x 642 shells stay apart to phi = 0.85, <Pi> = 18 Pi_0).
double default_vertex_radius(double thickness, double max_circumradius);

// The arguments a compress checkpoint was written with (io/checkpoint_file.hpp). Throws
// cmp::InputError(path, line, ...) for a missing file or one that is not a compress checkpoint.
std::vector<std::string> compress_checkpoint_args(const std::string& path);

// Runs the job. Throws cmp::InputError/UsageError for bad inputs (before any output exists),
// cmp::ComputationError when a relaxation fails or shells pass through each other.
void run_compress_job(const CompressJob& job, const std::string& provenance);

}  // namespace cmp::packrun
