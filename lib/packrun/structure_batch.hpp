#pragma once
// `shellpack structure`'s job: every packing read first (a bad file stops the run before any
// output exists), then the pooled g(r), the contact statistics per packing (in parallel), and
// the tables asked for, written atomically.
#include <string>
#include <vector>

namespace cmp::packrun {

struct StructureBatch {
  std::vector<std::string> inputs;  // extended XYZ packings ('-': stdin); every frame counts
  double bin_width = 0.01;          // g(r) bin [mean diameters]
  double r_max = 3.0;               // g(r) range [mean diameters]
  int force_bins = 40;              // bins of P(f/<f>) over [0, 4<f>)
  std::string output = "-";         // g(r) table
  std::string forces_output;        // force distribution ("" none)
  std::string summary_output;       // one row per packing ("" none)
  bool quiet = false;               // no summary lines
};

// Throws what the readers throw (cmp::InputError naming the file and line).
void run_structure_batch(const StructureBatch& b, const std::string& provenance);

}  // namespace cmp::packrun
