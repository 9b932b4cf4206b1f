#pragma once
// Sphere packings in extended XYZ, one per frame: the one reader behind `shellpack structure`
// and percolate, with one set of rules (one reader per format, strict: docs/formats.md):
//   - Lattice="Lx 0 0 0 Ly 0 0 0 Lz" is required, diagonal, with positive sides;
//   - pbc is read (no pbc with a Lattice means "T T T", as in ASE); PbcRule says whether
//     every axis must be periodic;
//   - the radius column is radius:R:1 (ours), Radius (OVITO's standard property; OVITO maps
//     the name without regard to case) or radii (the per-atom array name of ASE's tools);
//     every radius positive and finite;
//   - no two particles closer than 1e-9 of their summed radii (a duplicated particle; the
//     minimum image on the periodic axes);
//   - at least one sphere per frame.
// Each problem is a cmp::InputError naming the file and the line (the atom's row for a bad
// radius or a duplicate, the frame's first line otherwise).
#include "io/key_value_line.hpp"
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cmp::io {

class Input;
struct XyzFrame;

// Whether a packing must be periodic on every axis (shellpack structure) or is taken with the
// flags of its file (percolate).
enum class PbcRule { require_all, as_in_file };

struct SpherePackingFrame {
  std::string file;  // where the frame was read; empty for a frame built in memory
  long line = 0;     // the frame's atom count line
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  // Lattice diagonal [length units]
  std::array<bool, 3> pbc{true, true, true};
  mesh::VertexMatrix centres;  // #N by 3, as in the file (not wrapped)
  Eigen::VectorXd radii;       // #N, positive
  std::string radius_column;   // name of the column the radii came from
  KeyValues info;              // the other key=value pairs of the comment line, in order

  int size() const { return static_cast<int>(centres.rows()); }
  // Value of the first info pair with this key, or nullptr.
  const std::string* find_info(const std::string& key) const;
  // The info value of key as a positive finite number (strict: "2.0abc", "0x2" and "nan"
  // are errors at the frame's comment line); nullopt when the key is absent.
  std::optional<double> positive_info(const std::string& key) const;
};

// Radius column names accepted, in order of preference.
const std::vector<std::string>& radius_column_names();

// The packing held by one frame, checked by the rules above. Throws cmp::InputError for a
// frame read from a file, std::invalid_argument for one built in memory.
SpherePackingFrame sphere_packing_from_frame(const XyzFrame& frame, PbcRule rule);

// Every frame of an extended XYZ file ("-" = stdin) as packings, at least one.
std::vector<SpherePackingFrame> read_sphere_packing_xyz(const std::string& path, PbcRule rule);
std::vector<SpherePackingFrame> read_sphere_packing_xyz(Input& input, PbcRule rule);

}  // namespace cmp::io
