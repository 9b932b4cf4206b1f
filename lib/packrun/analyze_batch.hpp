#pragma once
// `shellpack analyze`'s job: every packing OFF read first (a bad file stops the run before
// any output exists), then analyzed (packings in parallel), then the tables asked for,
// written atomically: one summary row per packing (-o), and optionally g(r), one row per
// shell and one row per contact. Column names in docs/formats.md.
#include "packrun/packing_analysis.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace cmp::packrun {

struct AnalyzeBatch {
  std::vector<std::string> inputs;  // packing OFFs ('-': stdin)
  AnalyzeOptions options;
  std::string output = "-";         // summary table
  std::string rdf_output;           // g(r) per packing ("" none)
  std::string shells_output;        // one row per shell ("" none)
  std::string contacts_output;      // one row per contact and direction ("" none)
  bool quiet = false;               // no summary lines on stderr (warnings still come)
};

// Throws what the readers throw (cmp::InputError naming the file and line) and
// analyze_packing's refusals.
void run_analyze_batch(const AnalyzeBatch& b, const std::string& provenance);

// The tables, for tests and callers that hold analyses.
void write_analysis_summary(std::ostream& out, const std::vector<PackingAnalysis>& a, const std::string& provenance);
void write_analysis_rdf(std::ostream& out, const std::vector<PackingAnalysis>& a, const std::string& provenance);
void write_analysis_shells(std::ostream& out, const std::vector<PackingAnalysis>& a, const std::string& provenance);
void write_analysis_contacts(std::ostream& out, const std::vector<PackingAnalysis>& a, const std::string& provenance);

// The summary values of one analysis (means over shells and contacts); nullopt where the
// observable was not computed. Z = 2 contacts / N, dZ = Z - (6 - 4/N).
struct AnalysisSummary {
  std::optional<double> Z, dZ, turgor_mean, turgor_mean_p0, turgor_cv, force_normal_mean, force_normal_cv,
      force_tangential_mean, mu_eff, wall_pressure, coverage, wall_pressure_over_coverage, voronoi_faces_mean;
  std::optional<long> contacts;  // unordered pairs of shells (images counted apart)
  double asphericity_mean_d02 = 0, delta_eps_mean = 0;
};
AnalysisSummary summarise(const PackingAnalysis& a);

}  // namespace cmp::packrun
