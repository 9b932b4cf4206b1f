#pragma once
// What `shellpack jam` reports of its packings: the packing as an extended XYZ frame with its
// contacts and protocol figures (OVITO, ASE), a CSV row per packing, a one-line summary.
#include "spheres/jamming.hpp"

#include <cstdint>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace cmp::io {
struct XyzFrame;
}

namespace cmp::spheres {

// The packing of r with a `contacts` column and info pairs phi, Z, contacts, pressure_E,
// max_force_E, diameter, seed and tool (the provenance).
io::XyzFrame jammed_frame(const JammingResult& r, std::uint64_t seed, const std::string& provenance,
                          const HertzMaterial& material);

// The CSV of `shellpack jam`: the parameters as `# key=value` lines, then one row per packing
// (results[k] made from seeds[k]) with phi_J, Z, contacts, pressure, energy, max force, FIRE
// iterations, size changes and rejected tries by reason; the wall time (`seconds`) only when
// timings is set, so that by default a seed gives the same bytes on every run.
void write_jamming_table(std::ostream& out, const std::vector<JammingResult>& results,
                         const std::vector<std::uint64_t>& seeds, const JammingParameters& parameters,
                         const std::string& provenance, bool timings = false);

// "8 not isostatic, 3 rattlers" ("none" when all are 0), for progress notes and summaries.
std::string rejection_counts(int rattlers, int not_isostatic, int no_pressure_window, int fire_cap);

// The progress note of a batch of packings jammed in parallel: the tries and rejections of
// every seed so far, "try K, rejected: 3 rattlers, ...". update() may be called from any
// thread (each seed's progress callback).
class JammingProgressNote {
 public:
  explicit JammingProgressNote(std::size_t seeds) : latest_(seeds) {}
  // Records the latest progress of seed k; returns the note, or "" when the try is the same.
  std::string update(std::size_t k, const JammingProgressInfo& info);

 private:
  std::mutex mutex_;
  std::vector<JammingProgressInfo> latest_;
};

// One closing line for a --seeds run: count, mean and sd of phi_J, mean Z, tries and why the
// rejected ones were rejected, summed wall time.
std::string jamming_batch_summary(const std::vector<JammingResult>& results);

// "N = 50: phi_J = 0.62..., Z = ..., P = ..., ..." for stderr.
std::string jamming_summary(const JammingResult& r);

}  // namespace cmp::spheres
