#include "packrun/jam_batch.hpp"

#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/xyz.hpp"
#include "spheres/jamming_report.hpp"

#include <atomic>
#include <iostream>
#include <optional>

namespace cmp::packrun {

std::string jam_csv_path(const JamBatch& b) {
  if (!b.csv_output.empty()) return b.csv_output;
  return b.packing_output == "-" ? "" : "-";
}

void run_jam_batch(const JamBatch& b, const std::string& provenance) {
  const auto& p = b.jamming;
  const std::string csv = jam_csv_path(b);
  const bool csv_per_seed = csv.find("{seed}") != std::string::npos;
  const bool packing_per_seed = b.packing_output.find("{seed}") != std::string::npos;
  const auto seed_outputs = [&](std::uint64_t s) {
    std::vector<std::string> out;
    if (packing_per_seed) out.push_back(cli::expand_pattern(b.packing_output, "seed", std::to_string(s)));
    if (csv_per_seed) out.push_back(cli::expand_pattern(csv, "seed", std::to_string(s)));
    return out;
  };
  std::vector<std::uint64_t> seeds;
  for (const auto s : b.seeds)
    if (!(b.resume && cli::outputs_complete(seed_outputs(s)))) seeds.push_back(s);
  if (seeds.size() < b.seeds.size() && !b.quiet)
    std::cerr << "shellpack: --resume: " << b.seeds.size() - seeds.size() << " of " << b.seeds.size()
              << " seeds already done\n";
  // A warning, not chatter: said under -q too.
  const auto rarity = spheres::acceptance_warning(b.spheres, p);
  if (!rarity.empty()) std::cerr << "shellpack: warning: " << rarity << "\n";

  const long n = static_cast<long>(seeds.size());
  std::vector<spheres::JammingResult> results(static_cast<std::size_t>(n));
  cli::ProgressBar bar("jamming", static_cast<double>(n), b.quiet);
  std::atomic<long> done{0};
  // Tries and rejections so far, over every seed, for the bar's note.
  spheres::JammingProgressNote note(static_cast<std::size_t>(n));
  parallel_for_each_job(n, [&](long k) {
    results[k] = spheres::jam_spheres(b.spheres, seeds[k], p, [&](const spheres::JammingProgressInfo& info) {
      if (bar.enabled())
        if (auto text = note.update(static_cast<std::size_t>(k), info); !text.empty()) bar.set_note(text, true);
      return true;
    });
    const std::string seed = std::to_string(seeds[k]);
    if (packing_per_seed)
      io::write_xyz(cli::expand_pattern(b.packing_output, "seed", seed),
                    {spheres::jammed_frame(results[k], seeds[k], provenance, p.material)});
    if (csv_per_seed) {
      io::AtomicOutput out(cli::expand_pattern(csv, "seed", seed));
      spheres::write_jamming_table(out.stream(), {results[k]}, {seeds[k]}, p, provenance, b.timings);
      out.commit();
    }
    const long finished = ++done;
    bar.update(static_cast<double>(finished));
  });
  bar.finish();
  // The packings and the table are each a result: one that cannot be written (a full disk) is
  // said after the other is.
  io::SecondaryOutputs packings;
  if (!b.packing_output.empty() && !packing_per_seed) {
    std::vector<io::XyzFrame> frames;
    for (long k = 0; k < n; ++k) frames.push_back(spheres::jammed_frame(results[k], seeds[k], provenance, p.material));
    packings.attempt([&] { io::write_xyz(b.packing_output, frames); });
  }
  std::optional<io::AtomicOutput> table;
  if (!csv.empty() && !csv_per_seed) {
    spheres::write_jamming_table(table.emplace(csv).stream(), results, seeds, p, provenance, b.timings);
  }
  packings.commit_then_throw({table ? &*table : nullptr});
  if (!b.quiet && n == 1) std::cerr << "shellpack: " << spheres::jamming_summary(results.front()) << "\n";
  if (!b.quiet && n > 1) std::cerr << "shellpack: " << spheres::jamming_batch_summary(results) << "\n";
}

}  // namespace cmp::packrun
