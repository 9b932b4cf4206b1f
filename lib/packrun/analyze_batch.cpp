#include "packrun/analyze_batch.hpp"
#include "core/minimum_image.hpp"

#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <iostream>
#include <optional>

namespace cmp::packrun {

namespace {

using io::format_number;

std::string cell(const std::optional<double>& v) { return v ? format_number(*v) : std::string(); }
std::string cell(const std::optional<long>& v) { return v ? std::to_string(*v) : std::string(); }

std::string brief(const std::optional<double>& v) { return v ? fmt::format("{:.4g}", *v) : std::string("-"); }

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

const char* kUnits =
    "lengths u (the file's), pressures P (the unit of E), forces F = P u^2; _d0 in D0, _d02 in D0^2";

}  // namespace

AnalysisSummary summarise(const PackingAnalysis& a) {
  AnalysisSummary s;
  const double n = a.particles;
  if (a.has_contacts) {
    s.contacts = static_cast<long>(a.contacts.size() / 2);
    s.Z = a.particles > 0 ? static_cast<double>(a.contacts.size()) / n : 0.0;
    s.dZ = *s.Z - (6.0 - 4.0 / n);
  }
  if (!a.turgor.empty()) {
    s.turgor_mean = mean(a.turgor);
    s.turgor_cv = spheres::coefficient_of_variation(a.turgor);
    if (a.p0) s.turgor_mean_p0 = *s.turgor_mean / *a.p0;
  }
  if (a.has_forces) {
    std::vector<double> normal, tangential;
    for (const auto& c : a.contacts) {
      normal.push_back(c.normal.norm());
      tangential.push_back(c.tangential.norm());
    }
    s.force_normal_mean = mean(normal);
    s.force_normal_cv = spheres::coefficient_of_variation(normal);
    s.force_tangential_mean = mean(tangential);
    s.mu_eff = shell::effective_friction(a.contacts);
  }
  if (a.walls) {
    s.wall_pressure = a.walls->pressure();
    s.coverage = a.walls->coverage();
    if (*s.coverage > 0) s.wall_pressure_over_coverage = *s.wall_pressure / *s.coverage;
  }
  if (!a.voronoi_faces.empty()) {
    double f = 0;
    for (int x : a.voronoi_faces) f += x;
    s.voronoi_faces_mean = f / n;
  }
  for (const auto& sh : a.shapes) {
    s.asphericity_mean_d02 += sh.asphericity / (a.d0 * a.d0);
    s.delta_eps_mean += sh.aspect_deviation;
  }
  if (!a.shapes.empty()) {
    s.asphericity_mean_d02 /= n;
    s.delta_eps_mean /= n;
  }
  return s;
}

void write_analysis_summary(std::ostream& out, const std::vector<PackingAnalysis>& all, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("units", kUnits);
  csv.header({"file", "particles", "phi", "phi_source", "d0", "d0_source", "bending", "contacts", "Z", "dZ", "turgor_mean_P",
              "turgor_mean_P0", "turgor_cv", "asphericity_mean_d02", "delta_eps_mean", "force_normal_mean_F",
              "force_normal_cv", "force_tangential_mean_F", "mu_eff", "wall_pressure_P", "coverage",
              "wall_pressure_over_coverage_P", "voronoi_faces_mean"});
  for (const auto& a : all) {
    const auto s = summarise(a);
    csv.row({a.file, std::to_string(a.particles), format_number(a.phi), a.phi_source, format_number(a.d0), a.d0_source,
             a.bending, cell(s.contacts), cell(s.Z), cell(s.dZ), cell(s.turgor_mean), cell(s.turgor_mean_p0), cell(s.turgor_cv),
             format_number(s.asphericity_mean_d02), format_number(s.delta_eps_mean), cell(s.force_normal_mean),
             cell(s.force_normal_cv), cell(s.force_tangential_mean), cell(s.mu_eff), cell(s.wall_pressure),
             cell(s.coverage), cell(s.wall_pressure_over_coverage), cell(s.voronoi_faces_mean)});
  }
}

void write_analysis_rdf(std::ostream& out, const std::vector<PackingAnalysis>& all, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("units", "r in D0 (d0 of the summary); g normalised to the ideal gas of the same density");
  csv.header({"file", "r_d0", "g", "pairs"});
  for (const auto& a : all) {
    if (!a.rdf) continue;
    for (std::size_t b = 0; b < a.rdf->r.size(); ++b)
      csv.row({a.file, format_number(a.rdf->r[b]), format_number(a.rdf->g[b]), std::to_string(a.rdf->pair_counts[b])});
  }
}

void write_analysis_shells(std::ostream& out, const std::vector<PackingAnalysis>& all, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("units", kUnits);
  csv.header({"file", "shell", "x_u", "y_u", "z_u", "contacts", "volume_u3", "turgor_P", "gyration1_u2", "gyration2_u2",
              "gyration3_u2", "asphericity_u2", "delta_eps", "voronoi_faces"});
  for (const auto& a : all)
    for (std::size_t k = 0; k < a.shapes.size(); ++k) {
      const auto& s = a.shapes[k];
      Eigen::Vector3d c = s.centre;  // wrapped into the box for display
      for (int d = 0; d < 3; ++d) c[d] = wrap_into_period(c[d], a.box[d]);
      csv.row({a.file, std::to_string(k), format_number(c[0]), format_number(c[1]), format_number(c[2]),
               a.has_contacts ? std::to_string(a.contacts_per_shell[k]) : "", format_number(a.volumes[k]),
               a.turgor.empty() ? "" : format_number(a.turgor[k]), format_number(s.gyration[0]),
               format_number(s.gyration[1]), format_number(s.gyration[2]), format_number(s.asphericity),
               format_number(s.aspect_deviation), a.voronoi_faces.empty() ? "" : std::to_string(a.voronoi_faces[k])});
    }
}

void write_analysis_contacts(std::ostream& out, const std::vector<PackingAnalysis>& all, const std::string& provenance) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("units", kUnits);
  csv.meta("rows", "one per contact and direction: the force on shell m from shell n (image: n's periodic image seen from m)");
  csv.header({"file", "m", "n", "image_x", "image_y", "image_z", "vertex_pairs", "force_x_F", "force_y_F", "force_z_F",
              "force_normal_F", "force_tangential_F"});
  for (const auto& a : all)
    for (const auto& c : a.contacts) {
      const bool f = a.has_forces;
      csv.row({a.file, std::to_string(c.m), std::to_string(c.n), std::to_string(c.image[0]), std::to_string(c.image[1]),
               std::to_string(c.image[2]), std::to_string(c.vertex_pairs), f ? format_number(c.force[0]) : "",
               f ? format_number(c.force[1]) : "", f ? format_number(c.force[2]) : "",
               f ? format_number(c.normal.norm()) : "", f ? format_number(c.tangential.norm()) : ""});
    }
}

void run_analyze_batch(const AnalyzeBatch& b, const std::string& provenance) {
  std::vector<packing::ShellPackingFile> packings;
  for (const auto& path : b.inputs) packings.push_back(packing::read_shell_packing(path));
  AnalyzeOptions o = b.options;
  o.require_rdf = o.require_rdf || !b.rdf_output.empty();
  o.require_contacts = o.require_contacts || !b.contacts_output.empty();
  std::vector<PackingAnalysis> all(packings.size());
  parallel_for_each_job(static_cast<long>(packings.size()), [&](long k) { all[k] = analyze_packing(packings[k], o); });

  io::AtomicOutput out(b.output);
  std::optional<io::AtomicOutput> rdf_out, shells_out, contacts_out;
  if (!b.rdf_output.empty()) rdf_out.emplace(b.rdf_output);
  if (!b.shells_output.empty()) shells_out.emplace(b.shells_output);
  if (!b.contacts_output.empty()) contacts_out.emplace(b.contacts_output);
  write_analysis_summary(out.stream(), all, provenance);
  if (rdf_out) write_analysis_rdf(rdf_out->stream(), all, provenance);
  if (shells_out) write_analysis_shells(shells_out->stream(), all, provenance);
  if (contacts_out) write_analysis_contacts(contacts_out->stream(), all, provenance);
  io::commit_in_order({&out, rdf_out ? &*rdf_out : nullptr, shells_out ? &*shells_out : nullptr,
                       contacts_out ? &*contacts_out : nullptr});
  for (const auto& a : all)
    for (const auto& w : a.warnings) std::cerr << "shellpack: warning: " << w << "\n";
  if (!b.quiet)
    for (const auto& a : all) {
      const auto s = summarise(a);
      std::cerr << fmt::format("shellpack: {}: N = {}, phi = {:.4f} ({}), Z = {}, mu_eff = {}, Voronoi faces = {}\n", a.file,
                               a.particles, a.phi, a.phi_source, brief(s.Z), brief(s.mu_eff), brief(s.voronoi_faces_mean));
    }
}

}  // namespace cmp::packrun
