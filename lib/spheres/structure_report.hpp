#pragma once
// What `shellpack structure` reports of one or several packings: their contact statistics
// pooled, and the tables of g(r), of the contact force distribution and of each packing.
#include "spheres/structure.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace cmp::spheres {

// Contact statistics of several packings together. Forces are taken relative to their own
// packing's mean, so that packings at different pressures pool.
struct PooledContacts {
  std::vector<double> relative_forces;  // f / <f> of every contact of every packing
  double force_cv = 0;                  // coefficient of variation of relative_forces
  double mean_contact_number = 0;       // mean of the packings' Z
  long rattlers = 0;                    // over all packings
};
PooledContacts pool_contacts(const std::vector<ContactStatistics>& stats);

// g(r) CSV: provenance, packings, Z_mean, rattlers, force_cv, then r_d, g, pairs.
void write_rdf_table(std::ostream& out, const RadialDistribution& rdf, const PooledContacts& pooled,
                     std::size_t packings, const std::string& provenance);
// P(f/<f>) CSV over [0, 4<f>) in `bins` bins.
void write_force_distribution_table(std::ostream& out, const PooledContacts& pooled, int bins,
                                    const std::string& provenance);
// One row per packing (labels[k] names stats[k]): phi, Z, contacts, rattlers, pressure, forces.
void write_contact_summary_table(std::ostream& out, const std::vector<std::string>& labels,
                                 const std::vector<ContactStatistics>& stats, const std::string& provenance);
// "label: N = 50, phi = ..., Z = ..., ... rattlers, P = ..., contact force cv = ..." for stderr.
std::string contact_summary(const std::string& label, const ContactStatistics& s);

}  // namespace cmp::spheres
