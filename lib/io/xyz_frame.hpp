#pragma once
// One frame of extended XYZ (the particle format of docs/formats.md, read by OVITO and ASE): per-atom
// columns named by the Properties key, a cell (Lattice), periodic flags and other key=value
// pairs of the comment line.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace cmp::io {

// One per-atom property, e.g. pos:R:3. Atom i's components are [i*width, (i+1)*width).
struct XyzColumn {
  std::string name;
  char type = 'R';                   // 'R' real, 'I' integer, 'S' string, 'L' logical (T/F)
  int width = 1;                     // components per atom
  std::vector<double> values;        // R, I, L (1 = T, 0 = F): #atoms * width, atom after atom
  std::vector<std::string> strings;  // S: #atoms * width, no whitespace inside

  // Number of atoms the column holds.
  int rows() const;
};

struct XyzFrame {
  Eigen::Matrix3d lattice = Eigen::Matrix3d::Zero();  // rows: cell vectors a, b, c
  bool has_lattice = false;
  std::array<bool, 3> pbc{false, false, false};
  std::vector<XyzColumn> columns;                         // in Properties order
  std::vector<std::pair<std::string, std::string>> info;  // other comment-line pairs, in order
  std::string file;  // where the frame was read (for messages); empty when built in memory
  long line = 0;     // line of the frame's atom count

  // Number of atoms (rows of the first column; 0 without columns).
  int size() const;
  // The named column, or nullptr.
  const XyzColumn* find(const std::string& name) const;
  XyzColumn* find(const std::string& name);
  // The named column, checked: type must match and width too unless width is 0. Throws
  // cmp::InputError(file, line, ...) for a frame read from a file (std::invalid_argument for
  // one built in memory) when it is missing or does not match.
  const XyzColumn& column(const std::string& name, char type, int width = 0) const;

  // #atoms by 3 copy of the "pos" column (pos:R:3); throws as column().
  mesh::VertexMatrix positions() const;
  // The "species" column (species:S:1); throws as column().
  std::vector<std::string> species() const;
  // #atoms by width copy of a column of type R, I or L; throws as column().
  Eigen::MatrixXd real_column(const std::string& name) const;
  // Value of the first info pair with this key, or nullptr.
  const std::string* find_info(const std::string& key) const;

  // Adds column c, or replaces the column of the same name in place. Throws
  // std::invalid_argument when its size disagrees with the other columns, the name is empty
  // or holds ':' or whitespace, the type is not R/I/S/L, or the width is not positive.
  void add_column(XyzColumn c);
  // pos:R:3 from V (#atoms by 3).
  void set_positions(const mesh::VertexMatrix& V);
  // species:S:1, one name per atom (e.g. "H" or "X"; ASE wants element symbols).
  void set_species(const std::vector<std::string>& names);
  // name:R:w from an #atoms by w matrix (a vector gives w = 1).
  void set_real_column(const std::string& name, const Eigen::Ref<const Eigen::MatrixXd>& values);
  // name:I:1 from one integer per atom.
  void set_integer_column(const std::string& name, const std::vector<int>& values);
  // Sets key=value in info, replacing the first pair with this key or appending.
  void set_info(const std::string& key, const std::string& value);

  // Throws cmp::InputError(file, line, what), or std::invalid_argument(what) without a file.
  [[noreturn]] void fail(const std::string& what) const;
};

}  // namespace cmp::io
