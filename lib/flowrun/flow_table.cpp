#include "flowrun/flow_table.hpp"

#include "io/csv.hpp"
#include "lbm/collision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace cmp::flowrun {

namespace {

std::string num(double x) { return io::format_number(x); }
std::string opt(const std::optional<double>& x) { return x ? num(*x) : std::string(); }

const char* drive_name(lbm::Driving d) { return d == lbm::Driving::kPressure ? "pressure" : "force"; }

}  // namespace

std::vector<std::string> flow_columns(bool timings) {
  std::vector<std::string> c{"file", "format", "porosity", "porosity_source", "porosity_voxels",
                             "cluster_fraction", "dropped_pockets", "dropped_fraction", "delta", "d0", "scale",
                             "refine", "nx", "ny", "nz", "fluid_nodes", "flow_axis", "drive", "collision", "tau",
                             "walls", "permeability_lu", "permeability_delta2", "permeability_d02",
                             "permeability_u2", "tortuosity", "superficial_velocity_lu", "interstitial_velocity_lu",
                             "max_speed_lu", "pressure_gradient_lu", "reynolds", "mach", "steps", "converged",
                             "bytes_per_fluid_node"};
  if (timings) c.insert(c.end(), {"seconds", "mlups", "halo_bytes_per_step", "halo_seconds"});
  return c;
}

std::vector<std::string> flow_row(const FlowCase& c, const lbm::FlowSettings& s, const FlowOutcome& out,
                                  bool timings) {
  const auto& o = out.result.final;
  const double m = c.refine;
  const double kappa_delta2 = o.kappa_lu / (m * m);  // node side delta / M
  const double h = c.node_spacing[c.axis];             // node side in the input's length units
  const double nodes = static_cast<double>(c.nodes);
  std::vector<std::string> row{
      c.file, c.format, num(c.porosity), c.porosity_source, num(c.porosity_voxels),
      num(static_cast<double>(c.cluster_nodes) / nodes), std::to_string(c.dropped_pockets),
      num(static_cast<double>(c.dropped_nodes) / nodes), opt(c.delta), opt(c.d0), opt(c.scale),
      std::to_string(c.refine), std::to_string(c.voxels[0]), std::to_string(c.voxels[1]),
      std::to_string(c.voxels[2]), std::to_string(out.fluid_nodes), axis_name(c.axis), drive_name(s.driving),
      s.collision, num(s.collision_parameters.tau), c.interpolated_walls ? "interpolated" : "halfway",
      num(o.kappa_lu), num(kappa_delta2), c.d0 ? num(o.kappa_lu * (h / *c.d0) * (h / *c.d0)) : std::string(),
      num(o.kappa_lu * h * h), num(o.tortuosity), num(o.superficial_velocity), num(o.interstitial_velocity),
      num(o.max_speed), num(o.pressure_gradient), num(o.reynolds), num(o.mach), std::to_string(o.steps),
      out.result.converged ? "1" : "0", num(std::round(out.bytes_per_fluid_node * 100) / 100)};
  if (timings) {
    row.push_back(fmt::format("{:.3f}", out.seconds));
    row.push_back(fmt::format("{:.2f}", out.seconds > 0 ? static_cast<double>(out.fluid_nodes) * out.steps_run /
                                                             out.seconds / 1e6
                                                       : 0.0));
    row.push_back(fmt::format("{:.0f}", out.halo_bytes_per_step));
    row.push_back(fmt::format("{:.3f}", out.halo_seconds));
  }
  return row;
}

std::string flow_summary(const FlowCase& c, const FlowOutcome& out, bool timings) {
  const auto& r = out.result.final;
  std::string s = fmt::format("{}: kappa {:.6g} lu = {:.6g} delta^2{}, tau_H {:.6g}, porosity {:.4f}, {} fluid nodes "
                              "(M = {}), {} steps{}, Re {:.2g}, Ma {:.2g}",
                              c.file, r.kappa_lu, r.kappa_lu / (c.refine * c.refine),
                              c.d0 ? fmt::format(" = {:.6g} D0^2", r.kappa_lu * std::pow(c.node_spacing[c.axis] / *c.d0, 2)) : "",
                              r.tortuosity, c.porosity, out.fluid_nodes, c.refine, r.steps,
                              out.result.converged ? "" : " (not converged)", r.reynolds, r.mach);
  if (c.dropped_pockets > 0) s += fmt::format(", {} isolated pockets dropped", c.dropped_pockets);
  if (timings)
    s += fmt::format(", {:.2f} s, {:.1f} MLUPS", out.seconds,
                     out.seconds > 0 ? static_cast<double>(out.fluid_nodes) * out.steps_run / out.seconds / 1e6 : 0.0);
  return s;
}

void write_flow_meta(io::CsvWriter& csv, const std::string& provenance, const lbm::FlowSettings& s,
                     const lbm::ConvergenceSettings& conv) {
  csv.meta("provenance", provenance);
  csv.meta("lattice", "D3Q19");
  csv.meta("collision", s.collision);
  csv.meta("tau", num(s.collision_parameters.tau));
  csv.meta("magic", num(s.collision_parameters.magic));
  csv.meta("viscosity_lu", num((s.collision_parameters.tau - 0.5) / 3));
  csv.meta("precision", s.precision == lbm::Precision::kDouble ? "double" : "float");
  csv.meta("drive", drive_name(s.driving));
  if (s.driving == lbm::Driving::kPressure) csv.meta("density_drop", num(s.density_drop));
  else csv.meta("body_force", num(s.body_force));
  csv.meta("tol", num(conv.tol));
  csv.meta("check_every", std::to_string(conv.check_every));
  csv.meta("window", std::to_string(conv.window));
  csv.meta("max_steps", std::to_string(conv.max_steps));
  csv.meta("permeability", "nu <u_axis> / |grad p| with <u_axis> the superficial mean over the whole box "
                           "(solid nodes count as 0); |grad p| (pressure_gradient_lu) = c_s^2 density_drop / (n_axis - 1) "
                           "with the densities set on the first and last node planes, or the body force");
  csv.meta("units", "_lu lattice units (node side delta/M, time step); permeability_delta2 in voxel sides delta^2 "
                    "of the input image; permeability_d02 in D0^2; permeability_u2 in the input file's length unit "
                    "squared; tortuosity tau_H = sum|u| / sum u_axis over the fluid nodes");
}

std::vector<std::string> history_columns() {
  return {"file", "steps", "permeability_lu", "permeability_delta2", "tortuosity", "change", "mach", "mass"};
}

std::optional<double> relative_change(const std::vector<lbm::FlowObservables>& h, std::size_t k, long window) {
  if (k < static_cast<std::size_t>(window)) return std::nullopt;
  const auto& now = h[k];
  const auto& then = h[k - static_cast<std::size_t>(window)];
  return std::max(std::abs(now.kappa_lu - then.kappa_lu) / std::abs(now.kappa_lu),
                  std::abs(now.tortuosity - then.tortuosity) / std::abs(now.tortuosity));
}

std::vector<std::vector<std::string>> history_rows(const FlowCase& c, const lbm::SteadyStateResult& result,
                                                   long window) {
  std::vector<std::vector<std::string>> rows;
  const double m2 = 1.0 * c.refine * c.refine;
  for (std::size_t k = 0; k < result.history.size(); ++k) {
    const auto& o = result.history[k];
    const auto change = relative_change(result.history, k, window);
    rows.push_back({c.file, std::to_string(o.steps), num(o.kappa_lu), num(o.kappa_lu / m2), num(o.tortuosity),
                    change ? num(*change) : std::string(), num(o.mach), num(o.mass)});
  }
  return rows;
}

}  // namespace cmp::flowrun
