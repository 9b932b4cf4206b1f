#pragma once
// Packings of budding cells as extended XYZ frames (docs/formats.md), one row per lobe:
//   species pos(x y 0) radius cell lobe orientation pressure contacts
// species X (ASE's dummy element), lobe 0 for the mother and 1 for the bud, radius [sigma],
// orientation theta of the cell [rad, bud -> mother], pressure on the lobe sum|F|/(pi sigma_lobe)
// [k], contacts of the lobe. The plane is z = 0: Lattice="L 0 0 0 L 0 0 0 1", pbc="T T F"
// (periodic in x and y, a unit c vector that OVITO and ASE accept). Cell centres are wrapped
// into the box; a lobe may lie outside it.
//
// The reader takes any frame with these rules, each problem a cmp::InputError at file:line
// (the lobe's row, or the comment line for the box): a square diagonal Lattice with positive
// side, periodic in x and y; columns pos, radius, cell (I), lobe (I, 0 or 1); every cell id
// exactly twice, once per lobe; mother radius 1/2 (the unit sigma); bud radius in [0, 1/2];
// mother and bud tangent within 1e-6 sigma (nearest image). Other columns are ignored.
#include "cells2d/cell.hpp"
#include "cells2d/packing_analysis.hpp"
#include "io/key_value_line.hpp"
#include "io/xyz_frame.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cmp::cells2d {

struct CellPacking {
  double box = 0;           // side L [sigma]
  std::vector<Cell> cells;  // ordered by cell id
  io::KeyValues info;       // the comment line's other pairs
  std::string file;
  long line = 0;
};

// The columns every frame of budding cells starts with, one row per lobe (2i mother, 2i + 1
// bud of cell i): species X, pos (z = 0), radius, cell, lobe, orientation; the cells as given.
void set_lobe_columns(io::XyzFrame& frame, const std::vector<Cell>& cells);

// The frame of a packing; analysis (may be null) fills pressure and contacts (else 0).
// info pairs are appended to the comment line.
io::XyzFrame packing_frame(const std::vector<Cell>& cells, double box, const PackingAnalysis* analysis,
                           const std::vector<std::pair<std::string, std::string>>& info);

// The packing of a frame, checked by the rules above.
CellPacking packing_from_frame(const io::XyzFrame& frame);
// Every frame of a file ("-": stdin).
std::vector<CellPacking> read_packings(const std::string& path);

// The cells exactly as written to and read back from a file (centres wrapped into the box,
// then rebuilt from the lobe centres): computing on these gives the same numbers as on the
// file, to the last digit.
std::vector<Cell> canonical_cells(const std::vector<Cell>& cells, double box);

}  // namespace cmp::cells2d
