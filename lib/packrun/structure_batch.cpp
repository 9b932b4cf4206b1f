#include "packrun/structure_batch.hpp"

#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "spheres/structure_report.hpp"

#include <fmt/format.h>

#include <iostream>
#include <optional>

namespace cmp::packrun {

void run_structure_batch(const StructureBatch& b, const std::string& provenance) {
  std::vector<spheres::SpherePacking> packings;
  std::vector<std::string> labels;
  for (const auto& path : b.inputs) {
    auto frames = spheres::read_sphere_packings(path);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      labels.push_back(frames.size() > 1 ? fmt::format("{}#{}", path, f) : path);
      packings.push_back(std::move(frames[f]));
    }
  }
  const auto rdf = spheres::radial_distribution(packings, b.bin_width, b.r_max);
  std::vector<spheres::ContactStatistics> stats(packings.size());
  parallel_for_each_job(static_cast<long>(packings.size()),
                        [&](long k) { stats[k] = spheres::contact_statistics(packings[k]); });
  const auto pooled = spheres::pool_contacts(stats);

  io::AtomicOutput out(b.output);
  std::optional<io::AtomicOutput> forces_out, summary_out;
  if (!b.forces_output.empty()) forces_out.emplace(b.forces_output);
  if (!b.summary_output.empty()) summary_out.emplace(b.summary_output);
  spheres::write_rdf_table(out.stream(), rdf, pooled, packings.size(), provenance);
  if (forces_out) spheres::write_force_distribution_table(forces_out->stream(), pooled, b.force_bins, provenance);
  if (summary_out) spheres::write_contact_summary_table(summary_out->stream(), labels, stats, provenance);
  io::commit_in_order({&out, forces_out ? &*forces_out : nullptr, summary_out ? &*summary_out : nullptr});
  if (!b.quiet)
    for (std::size_t k = 0; k < stats.size(); ++k)
      std::cerr << "shellpack: " << spheres::contact_summary(labels[k], stats[k]) << "\n";
}

}  // namespace cmp::packrun
