#pragma once
// percolate's CSV tables read back as percolation samples (the input of percolate sweep and of
// percolation_probability): one PercolationSample per row, checked to be one kind of run.
#include "voxel/percolation_probability.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace cmp::voxel {

struct PercolationTables {
  std::vector<PercolationSample> samples;   // one per row, table after table, in file order
  std::set<std::string> scales;             // the values of the scale column (io::format_number), sorted
  std::map<std::string, std::string> same;  // connectivity, labelling (meta lines) and kind, marking,
                                            // flow_axis, porosity_method (columns) where given:
                                            // the one value of all tables
};

// Reads the CSV tables percolate wrote (paths; "-" = stdin) with io::read_csv: columns
// particles, delta, percolates and porosity_column (porosity or porosity_voxels) are
// required; file, frame, scale and the columns and meta lines of PercolationTables::same are
// optional. Throws cmp::InputError(file, line, ...) for: a file that is not a CSV (the reader's
// message, saying what percolate sweep needs); a required column missing (at the header line);
// particles not an integer >= 1, percolates not 0 or 1, delta, porosity or scale not finite
// numbers; a value of `same` that differs from the first one seen (naming where that was); the
// same run (file, frame, scale, delta) twice (a table given twice).
PercolationTables read_percolation_tables(const std::vector<std::string>& paths, const std::string& porosity_column);

}  // namespace cmp::voxel
