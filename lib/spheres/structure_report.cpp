#include "spheres/structure_report.hpp"

#include "io/csv.hpp"

#include <fmt/format.h>

namespace cmp::spheres {

using io::format_number;

PooledContacts pool_contacts(const std::vector<ContactStatistics>& stats) {
  PooledContacts p;
  double z_sum = 0;
  for (const auto& s : stats) {
    for (double f : s.forces) p.relative_forces.push_back(f / s.mean_force);
    z_sum += s.contact_number;
    p.rattlers += s.rattlers;
  }
  if (!stats.empty()) p.mean_contact_number = z_sum / stats.size();
  p.force_cv = coefficient_of_variation(p.relative_forces);
  return p;
}

void write_rdf_table(std::ostream& out, const RadialDistribution& rdf, const PooledContacts& pooled,
                     std::size_t packings, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("packings", std::to_string(packings));
  csv.meta("Z_mean", format_number(pooled.mean_contact_number));
  csv.meta("rattlers", std::to_string(pooled.rattlers));
  csv.meta("force_cv", format_number(pooled.force_cv));
  csv.meta("units", "r in mean diameters; g normalised to the ideal gas of the same density");
  csv.header({"r_d", "g", "pairs"});
  for (std::size_t b = 0; b < rdf.r.size(); ++b)
    csv.row({format_number(rdf.r[b]), format_number(rdf.g[b]), std::to_string(rdf.pair_counts[b])});
}

void write_force_distribution_table(std::ostream& out, const PooledContacts& pooled, int bins,
                                    const std::string& provenance) {
  const auto h = normalised_histogram(pooled.relative_forces, bins, 4.0);
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("contacts", std::to_string(pooled.relative_forces.size()));
  csv.meta("force_cv", format_number(pooled.force_cv));
  csv.header({"f_over_mean", "probability_density"});
  for (std::size_t b = 0; b < h.centres.size(); ++b) csv.row({format_number(h.centres[b]), format_number(h.density[b])});
}

void write_contact_summary_table(std::ostream& out, const std::vector<std::string>& labels,
                                 const std::vector<ContactStatistics>& stats, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.header({"packing", "N", "phi", "Z", "contacts", "rattlers", "Z_without_rattlers", "pressure_E",
              "mean_force_Ed2", "force_cv", "max_overlap_d"});
  for (std::size_t k = 0; k < stats.size(); ++k) {
    const auto& s = stats[k];
    csv.row({labels[k], std::to_string(s.spheres), format_number(s.volume_fraction), format_number(s.contact_number),
             std::to_string(s.contacts), std::to_string(s.rattlers), format_number(s.contact_number_without_rattlers),
             format_number(s.pressure), format_number(s.mean_force), format_number(s.force_cv),
             format_number(s.max_overlap)});
  }
}

std::string contact_summary(const std::string& label, const ContactStatistics& s) {
  return fmt::format("{}: N = {}, phi = {:.5f}, Z = {:.4f} ({} contacts), {} rattlers, P = {:.3g} E, "
                     "contact force cv = {:.3f}",
                     label, s.spheres, s.volume_fraction, s.contact_number, s.contacts, s.rattlers, s.pressure,
                     s.force_cv);
}

}  // namespace cmp::spheres
