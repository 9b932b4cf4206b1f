#pragma once
// `shellpack jam`'s whole job over its seeds: jammed packings in parallel (one per seed), each
// written as soon as it is done when the outputs name {seed}, else every packing as one frame
// of one XYZ and one table, in seed order; --resume skips the seeds whose outputs exist.
#include "spheres/jamming.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cmp::packrun {

struct JamBatch {
  int spheres = 0;
  spheres::JammingParameters jamming;
  std::vector<std::uint64_t> seeds;
  std::string packing_output;  // extended XYZ ("" none, '-' stdout); {seed}: one file per seed
  std::string csv_output;      // the table as given by --csv ("": the default, see jam_csv_path)
  bool resume = false;         // skip seeds whose per-seed outputs are complete
  bool timings = false;        // wall time column
  bool quiet = false;          // no summary lines
};

// Where the table goes: --csv, or stdout when the packing does not go there (`-o -` alone
// writes only the packing, so that `shellpack jam -o - | shellpack structure -` works); "" none.
std::string jam_csv_path(const JamBatch& b);

// Runs the batch; every output is written atomically. Throws what jam_spheres throws.
void run_jam_batch(const JamBatch& b, const std::string& provenance);

}  // namespace cmp::packrun
