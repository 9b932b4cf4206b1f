#pragma once
// A packing OFF of shells as `shellpack analyze` reads it (docs/formats.md "Packing OFF"):
// the mesh with each shell unwrapped across the periodic faces, the box, and the
// `# key=value` lines `shellpack compress` writes beside the packing lines:
//   # phi=0.85  # E=1  # nu=0.5  # thickness=0.02  # vertex_radius=0.02  # P0=0.0025
//   # bending=none  # turgor=Pi_1 ... Pi_K  # volume0=V0_1 ... V0_K  # D0=1
//   # contact=hertz-faces  # contact_distance=0.02
// (D0= is read with the packing, as percolate reads it.) Other comment lines (provenance,
// free text) are ignored.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>


namespace cmp::packing {

struct PackingKeys {
  std::optional<double> phi;             // volume fraction N V0 / L^3, as the writer computed it
  std::optional<double> youngs_modulus;  // E [pressure units], > 0
  std::optional<double> poisson_ratio;   // nu, in (-1, 0.5]
  std::optional<double> thickness;       // t [length], > 0
  std::optional<double> vertex_radius;   // R_v [length], > 0
  std::optional<std::string> contact;    // the contact style between shells (hertz-vertices, hertz-faces)
  std::optional<double> contact_distance;  // hertz-faces: delta [length], > 0
  std::optional<double> p0;              // initial turgor P0 [pressure], > 0
  std::optional<std::string> bending;    // bending style or "none"
  std::vector<double> turgor;            // Pi of each shell [pressure] (K values or none)
  std::vector<double> volume0;           // V0 of each shell [length^3], > 0 (K values or none)
};

// The keys of the comment lines (text without "# ", and the line of each) for a packing of `shells` shells. A line "key=value" (the
// first '=' splits; spaces around are ignored) with one of the keys above must hold what the
// key needs: one finite number in range, or exactly `shells` numbers for turgor and volume0;
// else cmp::InputError(path, line, "..."). A key given twice: the last counts.
PackingKeys parse_packing_keys(const std::vector<std::string>& comments, const std::vector<long>& lines,
                               const std::string& path, int shells);

struct ShellPackingFile {
  std::string file;
  mesh::VertexMatrix V;              // each shell unwrapped into one periodic image
  mesh::FaceMatrix F;
  std::vector<int> offsets;          // K + 1: shell k owns rows [offsets[k], offsets[k+1])
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  // [0, L) per axis
  std::array<bool, 3> periodic{false, false, false};  // a non-periodic axis has walls at 0 and L
  PackingKeys keys;
  double d0 = 1;          // D0 [length]
  std::string d0_source;  // option (set by the caller), file (D0=), volume0 (diameter of the sphere of the mean V0), shell_volume (of the mean enclosed volume)
  int shells() const { return static_cast<int>(offsets.size()) - 1; }
};

// Reads a packing OFF ('-': stdin) as percolate does (read_packings: unwrapping, D0),
// then its keys. Throws cmp::InputError(path, line, ...) for what that rejects (no '# box'
// line: not a packing OFF; no triangles; ...), an extended XYZ (spheres, not shells), and bad
// key lines (parse_packing_keys).
ShellPackingFile read_shell_packing(const std::string& path);

}  // namespace cmp::packing
