#pragma once
// The compression protocol of shell packings (thesis 5.2.1, B.3.1, Ch. 4): shells in a box,
// inflated at the turgor Pi_0 where the jammed sphere packing put them, then the box shrunk
// isotropically and affinely step by step (every shell's vertex centroid rescaled, the shell
// moved rigidly with it) by at most `step` D_0 along its longest side, with a full relaxation
// (FIRE; for the "volume" pressure model the constant-volume loop, relax.hpp) after every step.
// The volume fraction is phi = sum_i V0_i / (Lx Ly Lz), V0_i the volume of shell i inflated
// at Pi_0 in the start box. Each requested target phi is landed on exactly (the step before it
// is shortened).
//
// Observables per step (one CompressionRow): the box pressure from the contact virial, the
// turgor statistics, the contact number Z (the mean number of other shells a shell touches: two
// shells touch when the contact style finds any contact between them: overlapping vertex
// spheres for hertz-vertices, a vertex within delta of the other's surface for hertz-faces),
// the shape of each shell (gyration
// tensor of its vertices, Eq. 4.6), each term's energy and the relaxation's figures.
//
// The shells are kept whole (unwrapped); after each step a shell whose vertex centroid left
// the box is moved back by a box vector. Everything is deterministic: the same start gives the
// same bits on any thread count.
//
// The rigid-box variant (options.walls; Fig. 4.5, B.3.1): after the inflation in the jammed
// periodic packing, the shells' vertex centroids are spread affinely (the shells moved rigidly)
// until the box enclosing them, with a gap of R_v between the outermost vertex spheres and each
// wall, holds phi_start. Then the box [0, L) has rigid walls on its six faces (hertz-walls) and
// no periodic images. A box step moves every wall inward by the same amount (both walls of an
// axis by half the side's change; the frame keeps the walls at 0 and L); the shells are not
// rescaled: a shell the moving wall reaches is translated rigidly by the wall's advance into it
// (the start of the relaxation, which then resolves the shell-shell overlaps this causes). While
// the bounding spheres of the shells (with R_v) are apart by g, and narrower than the box, a
// step may shrink the box side by up to g instead of `step` (two swept shells approach by at
// most the side's change, so the sweep leaves them untouched and the relaxation has nothing to
// do): the dilute approach costs a few steps, and shells the walls push are never deformed.
#include "shell/relax.hpp"
#include "shell/shell_model.hpp"
#include "shell/shell_packing.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cmp::shell {

struct CompressionOptions {
  ShellModel model;            // pressure "volume" or "turgor"; shell_contact_style and its contact parameters set
  double turgor0 = 0.0025;     // Pi_0 [the unit of E] (the thesis: Pi_0 / E = 0.0025)
  double step = 0.004;         // largest box side change per step [D_0]
  std::vector<double> targets; // target phi, ascending
  // The targets are dphi = phi - phi_J instead (phi_J known once the shells are inflated):
  // they become phi_J + dphi, rounded to 6 decimals, at start() and restore().
  bool targets_relative = false;
  RelaxParameters relax;       // force_scale is set from the mesh (E t a)
  // Above 0: the relative force tolerance of the box steps that land on no target, in place
  // of relax.relative_tolerance (which the targets keep). The path between two targets needs
  // no tight equilibrium: the next step moves every shell again at once (docs/study.md has
  // the measurements: 2.9 times fewer FIRE iterations at 1e-3, the structure at the targets
  // the same within the spread between packings). 0: every step at relax's tolerance.
  double between_tolerance = 0;
  bool walls = false;          // the rigid-box variant (model.contact.wall_modulus: E_w, rigid by default)
  double phi_start = 0.08;     // walls: the dilute start, below the jammed phi
};

struct CompressionRow {
  long step = 0;
  double phi = 0, dphi = 0;     // phi and phi - phi_J
  double box_side = 0;          // longest box side [D_0]
  double pressure = 0;          // contact virial pressure [units of E]
  double turgor_mean = 0, turgor_cv = 0;  // <Pi>/Pi_0 and sigma(Pi)/<Pi>
  double Z = 0, dZ = 0;         // contact number and Z - (6 - 4/N)
  long contacts = 0;            // contacts: touching shell pairs, each periodic image apart
  double asphericity = 0;       // mean b = l1^2 - (l2^2 + l3^2)/2 [D_0^2]
  double delta_eps = 0;         // mean l1/l3 - 1
  double volume_error = 0;      // max_i |V_i - V0_i| / V0_i
  double energy = 0;            // total [E D_0^3]
  std::vector<double> term_energies;
  double wall_pressure = 0;     // walls: total normal wall force / total wall area [units of E]
  double coverage = 0;          // walls: Theta, wall-touching face area / wall area (shell/wall_load.hpp)
  RelaxResult relax;
  std::optional<std::size_t> target;  // the index of the target phi this step landed on
};

// What a checkpoint needs to continue the protocol.
struct CompressionState {
  long step = 0;
  Eigen::Vector3d box = Eigen::Vector3d::Ones();
  std::size_t next_target = 0;
  double phi_jammed = 0;
  Eigen::VectorXd x;
  std::vector<double> turgor, volume0;
};

class Compression {
 public:
  // Builds the shell system of the packing (throws cmp::UsageError for bad parameters).
  Compression(ShellPacking packing, CompressionOptions options);

  // Inflates at Pi_0 in the start box, fixes V0 and phi_J (walls: then spreads the shells to
  // phi_start, cmp::UsageError when phi_start is not below what the inflated packing allows);
  // the row of step 0.
  CompressionRow start(const RelaxProgress& progress = {});
  // Continues from a saved state (of the same packing and options; targets at or below the
  // state's phi are skipped, so a resume may change --phi).
  void restore(const CompressionState& state);
  CompressionState state() const;

  // True when every target has been landed on.
  bool done() const { return next_target_ >= options_.targets.size(); }
  // One box step and its relaxation.
  CompressionRow advance(const RelaxProgress& progress = {});

  double phi() const;
  double phi_jammed() const { return phi_jammed_; }
  long step_index() const { return step_; }
  const Eigen::Vector3d& box() const { return box_; }
  const ShellSystem& system() const { return system_; }
  const ShellPacking& packing() const { return packing_; }
  const CompressionOptions& options() const { return options_; }
  std::vector<std::string> term_names() const;
  // The observables at the current state (relax and target left empty).
  CompressionRow observe() const;

 private:
  void set_box(const Eigen::Vector3d& box);
  void wrap_shells();
  void resolve_relative_targets();  // dphi -> phi_J + dphi (once); throws cmp::UsageError above 1
  std::vector<Eigen::Vector3d> centroids() const;
  void open_box();  // walls: the dilute start from the inflated periodic packing
  double free_advance() const;  // walls: the box side change no rigid sweep can bring shells into contact by
  void sweep(double s);        // walls: the box times s, walls moving in, shells pushed rigidly
  bool open_ = false;          // walls in place (no periodic images)
  ShellPacking packing_;
  CompressionOptions options_;
  ShellSystem system_;
  RelaxParameters relax_;
  std::vector<int> offsets_;  // first vertex of each shell, K + 1
  Eigen::Vector3d box_;
  long step_ = 0;
  std::size_t next_target_ = 0;
  double phi_jammed_ = 0;
  std::vector<double> relative_targets_;  // the dphi as given, when options.targets_relative
};

}  // namespace cmp::shell
