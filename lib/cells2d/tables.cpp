#include "cells2d/tables.hpp"

#include "cells2d/packing_xyz.hpp"
#include "cli/value_list.hpp"
#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cmp::cells2d {

namespace {
std::string num(double x) { return io::format_number(x); }
std::string num(long x) { return std::to_string(x); }
std::string num(int x) { return std::to_string(x); }

double parse_value(const std::string& token, const std::string& text) {
  double v = 0;
  if (!io::try_parse_double(token, v)) throw UsageError("'" + token + "' in '" + text + "' is not a number");
  return v;
}

}  // namespace

std::vector<std::string> growth_columns() {
  return {"step", "time", "dt", "cells", "phi", "pressure", "Z", "f_u", "rattlers", "mean_rate", "energy_per_cell",
          "rejected", "fire_iterations"};
}

std::vector<std::string> growth_row(const StepRecord& r) {
  const PackingAnalysis& p = *r.packing;
  return {num(r.step), num(r.time), num(r.dt), num(p.cells), num(p.area_fraction), num(p.pressure), num(p.Z),
          num(p.f_u), num(p.rattlers), num(p.mean_rate), num(p.energy / p.cells), num(r.rejections), num(r.iterations)};
}

std::vector<std::string> packing_columns() {
  return {"cells", "box", "phi", "pressure", "pressure_xx", "pressure_yy", "pressure_xy", "B", "G", "Z", "Z_iso",
          "f_u", "rattlers", "contacts", "energy_per_cell", "relaxed"};
}

std::vector<std::string> packing_row(const Moduli& m, double box) {
  const PackingAnalysis& p = m.packing;
  return {num(p.cells), num(box), num(p.area_fraction), num(p.pressure), num(p.pressure_tensor(0, 0)),
          num(p.pressure_tensor(1, 1)), num(p.pressure_tensor(0, 1)), num(m.bulk), num(m.shear), num(p.Z),
          num(p.Z_iso), num(p.f_u), num(p.rattlers), num(p.network_contacts), num(p.energy / p.cells),
          std::string(m.relaxed ? "1" : "0")};
}

std::vector<double> parse_dphi_list(const std::string& text) {
  std::vector<double> out = cli::parse_value_list(text);
  for (double v : out)
    if (v < 0) throw UsageError("'" + text + "': dphi must not be negative");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double parse_feedback(const std::string& text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  const double v = parse_value(text, text);
  if (!(v > 0)) throw UsageError("P0 must be positive (inf for no feedback), got '" + text + "'");
  return v;
}

std::vector<double> parse_feedback_list(const std::string& text) {
  std::vector<double> out;
  for (const auto& t : cli::split_fields(text, ',')) out.push_back(parse_feedback(t));
  if (out.empty()) throw UsageError("empty list");
  return out;
}

std::vector<std::string> sweep_columns() {
  std::vector<std::string> c = {"seed", "P0", "dphi", "phi_J"};
  for (const auto& k : packing_columns()) c.push_back(k);
  c.push_back("mean_rate");
  c.push_back("accepted_steps");
  c.push_back("fire_iterations");
  return c;
}

std::vector<std::vector<std::string>> sweep_seed(std::uint64_t seed, const GrowthParameters& parameters,
                                                 const std::vector<double>& dphis, const std::vector<double>& P0s) {
  std::vector<std::vector<std::string>> rows;
  Colony jammed(parameters, seed);
  jammed.grow_to_jamming();
  const ContactLawStyle& law = contact_law(parameters.contact);
  for (double P0 : P0s) {
    Colony colony(jammed);
    colony.set_feedback(P0);
    for (double dphi : dphis) {
      if (dphi > 0) colony.grow_beyond(dphi);
      const Moduli m = measure_moduli(canonical_cells(colony.cells(), parameters.box), parameters.box, law);
      std::vector<std::string> row = {std::to_string(seed), num(P0), num(dphi), num(colony.phi_jamming())};
      for (auto& v : packing_row(m, parameters.box)) row.push_back(v);
      row.push_back(num(m.packing.mean_rate));
      row.push_back(num(colony.counters().accepted));
      row.push_back(num(colony.counters().iterations));
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace cmp::cells2d
