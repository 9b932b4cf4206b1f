#pragma once
// The Chapter 4 observables of one packing of shells (`shellpack analyze`): volume fraction,
// g(r) of the shell centres, contacts and Z, shapes, turgor, inter-shell contact forces and
// mu_eff, the load on rigid walls, and the facets of the periodic Voronoi cells. Each
// observable is computed when the packing holds what it needs (a value from the file or an
// option); otherwise it is left out with one warning, or, when the user asked for it
// explicitly (a table of it), the packing is refused.
#include "packing/shell_packing_file.hpp"
#include "shell/shell_contact_forces.hpp"
#include "shell/shell_shapes.hpp"
#include "shell/wall_load.hpp"
#include "spheres/structure.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cmp::packrun {

struct AnalyzeOptions {
  // Overrides of the file's values (unset: the file's).
  std::optional<double> youngs_modulus, poisson_ratio, vertex_radius, contact_distance, d0, p0;
  std::optional<std::string> contact;  // hertz-vertices or hertz-faces
  double wall_modulus = std::numeric_limits<double>::infinity();  // E_w [pressure]; rigid by default
  double wall_poisson_ratio = 0.5;
  double bin_width = 0.01;  // g(r) bin [D0]
  double r_max = 3.0;       // g(r) range [D0]
  // Tables asked for: what they need must be there (an input error otherwise).
  bool require_rdf = false, require_contacts = false;
};

struct PackingAnalysis {
  std::string file;
  int particles = 0;
  double phi = 0;
  std::string phi_source;  // file (phi=), volume0 (sum V0 / box volume), shell_volumes (enclosed volumes)
  double d0 = 1;
  std::string d0_source;
  std::string bending;  // the file's bending= (a style or none; empty when absent)
  Eigen::Vector3d box = Eigen::Vector3d::Ones();
  std::vector<double> volumes;              // enclosed volume per shell [length^3]
  std::vector<shell::ShellShape> shapes;    // per shell
  std::vector<double> turgor;               // per shell (empty: unknown)
  std::optional<double> p0;
  bool has_contacts = false;                // the contact law known (R_v, or delta for hertz-faces)
  std::string contact;                      // its style
  std::vector<shell::ShellContact> contacts;  // both directions (m, n) and (n, m)
  std::vector<int> contacts_per_shell;
  bool has_forces = false;                  // E, nu known too
  std::optional<shell::WallLoad> walls;     // a non-periodic axis and E, nu, R_v known
  std::vector<int> voronoi_faces;           // per shell (empty: not a periodic cube)
  std::optional<spheres::RadialDistribution> rdf;  // periodic on every axis
  std::vector<std::string> warnings;        // one line each, without the program's name
};

// Everything computable for p under o. Throws cmp::InputError(p.file, 0, ...) when a table
// the user asked for cannot be made, or two shells share their centre.
PackingAnalysis analyze_packing(const packing::ShellPackingFile& p, const AnalyzeOptions& o);

}  // namespace cmp::packrun
