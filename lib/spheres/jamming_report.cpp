#include "spheres/jamming_report.hpp"

#include "io/csv.hpp"
#include "io/xyz_frame.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/rattlers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::spheres {

using io::format_number;

io::XyzFrame jammed_frame(const JammingResult& r, std::uint64_t seed, const std::string& provenance,
                          const HertzMaterial& material) {
  auto frame = packing_to_frame(r.packing);
  HertzSpheres system(r.packing.box, r.packing.radii, material, 0.0);
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(r.packing.positions.data(), 3L * r.packing.size());
  frame.set_integer_column("contacts", contact_counts(r.packing.size(), system.evaluate(x).contacts));
  frame.set_info("tool", provenance);
  frame.set_info("seed", std::to_string(seed));
  frame.set_info("phi", format_number(r.packing.volume_fraction()));
  frame.set_info("Z", format_number(r.contact_number()));
  frame.set_info("contacts", std::to_string(r.contacts));
  frame.set_info("pressure_E", format_number(r.pressure));
  frame.set_info("max_force_E", format_number(r.max_force));
  frame.set_info("diameter", format_number(r.packing.mean_diameter()));
  return frame;
}

void write_jamming_table(std::ostream& out, const std::vector<JammingResult>& results,
                         const std::vector<std::uint64_t>& seeds, const JammingParameters& p,
                         const std::string& provenance, bool timings) {
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("E", format_number(p.material.youngs_modulus));
  csv.meta("nu", format_number(p.material.poisson_ratio));
  csv.meta("P_min", format_number(p.min_pressure));
  csv.meta("eps_r", format_number(p.initial_step));
  csv.meta("phi_0", format_number(p.initial_volume_fraction));
  csv.meta("polydispersity", format_number(p.polydispersity));
  csv.meta("force_tolerance", format_number(p.fire.force_tolerance));
  csv.meta("units", "pressure in E, energy in E d^3 (d: jammed diameter); max_force in the packing file's units "
                    "(E times length^2, lengths such that d is about 1), the units of --ftol");
  std::vector<std::string> header{"seed", "N", "phi_J", "Z", "contacts", "contacts_isostatic", "pressure_E",
                                  "energy_Ed3", "max_force", "box_side_d", "fire_iterations", "size_changes",
                                  "rejected_tries", "rejected_rattlers", "rejected_not_isostatic",
                                  "rejected_no_pressure_window", "rejected_fire_cap"};
  if (timings) header.push_back("seconds");
  csv.header(header);
  for (std::size_t k = 0; k < results.size(); ++k) {
    const auto& r = results[k];
    const int n = r.packing.size();
    const double d = r.packing.mean_diameter();
    std::vector<std::string> row{std::to_string(seeds[k]), std::to_string(n), format_number(r.packing.volume_fraction()),
             format_number(r.contact_number()), std::to_string(r.contacts), std::to_string(isostatic_contacts(n)),
             format_number(r.pressure), format_number(r.energy / (d * d * d)), format_number(r.max_force),
             format_number(r.packing.box[0] / d), std::to_string(r.fire_iterations), std::to_string(r.size_changes),
             std::to_string(r.rejected_tries), std::to_string(r.rejected_for_rattlers),
             std::to_string(r.rejected_not_isostatic), std::to_string(r.rejected_no_pressure_window),
             std::to_string(r.rejected_fire_cap)};
    if (timings) row.push_back(fmt::format("{:.4f}", r.seconds));
    csv.row(row);
  }
}

std::string jamming_summary(const JammingResult& r) {
  const int n = r.packing.size();
  return fmt::format("N = {}: phi_J = {:.5f}, Z = {:.4f} ({} contacts, isostatic {}), P = {:.3g} E, "
                     "max|F| = {:.2g} E, {} FIRE iterations, {} rejected tries, {:.2f} s",
                     n, r.packing.volume_fraction(), r.contact_number(), r.contacts, isostatic_contacts(n), r.pressure,
                     r.max_force, r.fire_iterations, r.rejected_tries, r.seconds);
}

std::string rejection_counts(int rattlers, int not_isostatic, int no_pressure_window, int fire_cap) {
  std::string text;
  const auto add = [&](int count, const char* what) {
    if (count > 0) text += fmt::format("{}{} {}", text.empty() ? "" : ", ", count, what);
  };
  add(not_isostatic, "not isostatic");
  add(rattlers, "rattlers");
  add(no_pressure_window, "no pressure window");
  add(fire_cap, "FIRE cap");
  return text.empty() ? "none" : text;
}

std::string jamming_batch_summary(const std::vector<JammingResult>& results) {
  if (results.empty()) return "no packings";
  double phi = 0, phi2 = 0, z = 0, seconds = 0;
  int rattlers = 0, not_isostatic = 0, no_window = 0, fire_cap = 0, tries = 0;
  for (const auto& r : results) {
    const double f = r.packing.volume_fraction();
    phi += f, phi2 += f * f, z += r.contact_number(), seconds += r.seconds;
    rattlers += r.rejected_for_rattlers, not_isostatic += r.rejected_not_isostatic;
    no_window += r.rejected_no_pressure_window, fire_cap += r.rejected_fire_cap;
    tries += r.rejected_tries + 1;
  }
  const double k = static_cast<double>(results.size());
  const double mean = phi / k, sd = k > 1 ? std::sqrt(std::max(0.0, (phi2 - k * mean * mean) / (k - 1))) : 0.0;
  return fmt::format("{} packings of N = {}: phi_J = {:.5f} (sd {:.5f}), Z = {:.4f}, {} tries ({} rejected: {}), "
                     "{:.2f} s of jamming",
                     results.size(), results.front().packing.size(), mean, sd, z / k, tries,
                     tries - static_cast<int>(results.size()),
                     rejection_counts(rattlers, not_isostatic, no_window, fire_cap), seconds);
}

std::string JammingProgressNote::update(std::size_t k, const JammingProgressInfo& info) {
  std::lock_guard lock(mutex_);
  if (latest_[k].attempt == info.attempt && info.attempt != 0) return "";  // same try: nothing new
  latest_[k] = info;
  int tries = 0, rattlers = 0, not_isostatic = 0, no_window = 0, fire_cap = 0;
  for (const auto& l : latest_) {
    tries += l.attempt + 1, rattlers += l.rejected_for_rattlers, not_isostatic += l.rejected_not_isostatic;
    no_window += l.rejected_no_pressure_window, fire_cap += l.rejected_fire_cap;
  }
  return fmt::format("try {}, rejected: {}", tries, rejection_counts(rattlers, not_isostatic, no_window, fire_cap));
}

}  // namespace cmp::spheres
