#include "shell/mechanics_benchmarks.hpp"

#include "shell/membrane_squeeze.hpp"
#include "shell/sphere_inflation.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

namespace cmp::shell {

namespace {

using io::format_number;

void write_sphere(bool quick, std::ostream& out, const std::string& provenance,
                  const std::function<void(const std::string&)>& note) {
  SphereInflationCase c;
  if (quick) {
    c.loads = {1e-4, 1e-3, 1e-2};
  } else {
    c.loads = {1e-4, 2e-4, 5e-4, 1e-3, 1.5e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 7e-3, 8e-3, 9e-3, 1e-2};
  }
  if (note) note(fmt::format("sphere: icosahedral level {}, {} loads, {} models", c.level, c.loads.size(), c.models.size()));
  const auto rows = sphere_inflation(c);
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("case", "sphere (B.5.1, Fig. B.4A): strain eps_r = cbrt(V/V0) - 1 of an inflated sphere");
  csv.meta("R0", format_number(c.radius));
  csv.meta("E", format_number(c.material.youngs_modulus));
  csv.meta("nu", format_number(c.material.poisson_ratio));
  csv.meta("t", format_number(c.material.thickness));
  csv.meta("level", std::to_string(c.level));
  csv.meta("columns", "load_E = dP/E; eps_r of the mesh; eps_r_svk the SVK sphere (corrected B.81); eps_r_printed the "
                      "printed B.82; eps_r_linear the small-strain limit; rel_error = eps_r/eps_r_svk - 1");
  csv.header({"model", "load_E", "eps_r", "eps_r_svk", "eps_r_printed", "eps_r_linear", "rel_error", "iterations",
              "residual"});
  for (const auto& r : rows)
    csv.row({r.model, format_number(r.load), format_number(r.strain), format_number(r.strain_corrected),
             format_number(r.strain_printed), format_number(r.strain_linear),
             format_number(r.strain / r.strain_corrected - 1), std::to_string(r.relax.iterations),
             format_number(r.relax.residual)});
}

void write_plates_contact(bool quick, std::ostream& out, const std::string& provenance,
                          const std::function<void(const std::string&)>& note) {
  MembraneSqueezeCase c;
  if (quick) {
    c.level = 4;
    c.compressions = {0.05, 0.1, 0.2};
  } else {
    c.compressions = {0.01, 0.02, 0.04, 0.06, 0.08, 0.1, 0.125, 0.15, 0.175, 0.2, 0.25, 0.3, 0.35, 0.4};
  }
  if (note) note(fmt::format("plates-contact: icosahedral level {}, {} compressions", c.level, c.compressions.size()));
  const auto rows = membrane_squeeze(c);
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("case", "plates-contact (B.6, Fig. B.9): inflated SVK membrane, constant volume, between rigid plates");
  csv.meta("R0", format_number(c.radius));
  csv.meta("E", format_number(c.material.youngs_modulus));
  csv.meta("nu", format_number(c.material.poisson_ratio));
  csv.meta("t", format_number(c.material.thickness));
  csv.meta("P_i_E", format_number(c.inflation));
  csv.meta("vertex_radius", format_number(c.vertex_radius));
  csv.meta("level", std::to_string(c.level));
  csv.meta("columns", "compression X = 1 - eta/R_i (eta = gap/2 - R_v); force_hat = F/(E t R0) per plate; "
                      "pressure_star = P/P_i; *_theory from the shooting solution");
  csv.header({"compression", "gap", "force_hat", "force_hat_theory", "pressure_star", "pressure_star_theory",
              "contact_radius_theory_R0", "volume_error", "iterations", "volume_updates", "residual"});
  for (const auto& r : rows)
    csv.row({format_number(r.compression), format_number(r.gap), format_number(r.force), format_number(r.force_theory),
             format_number(r.pressure), format_number(r.pressure_theory), format_number(r.contact_radius_theory),
             format_number(r.volume_error), std::to_string(r.relax.iterations), std::to_string(r.relax.volume_updates),
             format_number(r.relax.residual)});
}

struct Case {
  const char* name;
  void (*run)(bool, std::ostream&, const std::string&, const std::function<void(const std::string&)>&);
};

const Case kCases[] = {
    {"sphere", &write_sphere},
    {"plates-contact", &write_plates_contact},
};

}  // namespace

std::vector<std::string> mechanics_benchmark_names() {
  std::vector<std::string> names;
  for (const auto& c : kCases) names.push_back(c.name);
  return names;
}

void check_mechanics_benchmark(const std::string& name) {
  std::string known;
  for (const auto& c : kCases) {
    if (name == c.name) return;
    known += (known.empty() ? "" : ", ") + std::string(c.name);
  }
  throw UsageError("unknown benchmark '" + name + "' (known: " + known + ")");
}

void run_mechanics_benchmark(const std::string& name, bool quick, std::ostream& out, const std::string& provenance,
                             const std::function<void(const std::string&)>& note) {
  check_mechanics_benchmark(name);
  for (const auto& c : kCases)
    if (name == c.name) c.run(quick, out, provenance, note);
}

}  // namespace cmp::shell
