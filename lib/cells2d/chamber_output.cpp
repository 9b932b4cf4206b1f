#include "cells2d/chamber_output.hpp"

#include "cells2d/packing_xyz.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <numbers>

namespace cmp::cells2d {

std::vector<std::string> chamber_columns() {
  return {"time",           "steps",       "cells", "chamber_cells", "left",  "pressure_walls",
          "pressure_virial", "growth_rate", "c_P",   "energy",        "max_force"};
}

std::vector<std::string> chamber_row(const ChamberSample& s) {
  const auto num = [](double v) { return io::format_number(v); };
  return {num(s.time),
          std::to_string(s.steps),
          std::to_string(s.cells),
          std::to_string(s.chamber_cells),
          std::to_string(s.left),
          num(s.pressure_walls),
          num(s.pressure_virial),
          num(s.growth_rate),
          num(s.cell_pressure_cv),
          num(s.energy),
          num(s.max_force)};
}

std::vector<std::pair<std::string, std::string>> chamber_info(const ChamberParameters& p, std::uint64_t seed) {
  const auto num = [](double v) { return io::format_number(v); };
  const ChamberGeometry& g = p.geometry;
  return {{"seed", std::to_string(seed)},          {"width", num(g.width)},
          {"height", num(g.height)},               {"outlet", num(g.outlet)},
          {"channel", num(g.channel)},             {"contact", p.contact},
          {"attraction", num(p.attraction)},       {"mobility", num(p.mobility)},
          {"dt", num(p.time_step())},              {"integrator", p.integrator},
          {"rate_spread", num(p.rate_spread)},     {"P0", num(p.P0)},
          {"feedback_pressure", p.feedback_pressure}, {"feedback_interval", num(p.feedback_interval)}};
}

io::XyzFrame chamber_frame(ChamberRun& run, const std::vector<std::pair<std::string, std::string>>& info) {
  const ChamberGeometry& g = run.parameters().geometry;
  const std::vector<Cell>& cells = run.cells();
  const LobeLoads loads = run.lobe_loads();
  io::XyzFrame frame;
  frame.has_lattice = true;
  frame.lattice = Eigen::Matrix3d::Identity();
  frame.lattice(0, 0) = g.width;
  frame.lattice(1, 1) = g.height + g.channel;
  frame.pbc = {false, false, false};
  set_lobe_columns(frame, cells);
  const auto lobes = static_cast<Eigen::Index>(2 * cells.size());
  Eigen::VectorXd force(lobes), pressure(lobes);
  std::vector<int> contacts(static_cast<std::size_t>(lobes));
  for (std::size_t l = 0; l < 2 * cells.size(); ++l) {
    const auto r = static_cast<Eigen::Index>(l);
    const double radius = 0.5 * lobe_diameter(cells[l / 2], static_cast<int>(l % 2));
    force[r] = loads.force[l];
    pressure[r] = radius > 0 ? loads.force[l] / (2 * std::numbers::pi * radius) : 0.0;
    contacts[l] = loads.contacts[l];
  }
  frame.set_real_column("force", force);
  frame.set_real_column("pressure", pressure);
  frame.set_integer_column("contacts", contacts);
  frame.set_info("Origin", fmt::format("0 {} 0", io::format_number(-g.channel)));
  frame.set_info("time", io::format_number(run.time()));
  for (const auto& [k, v] : info) frame.set_info(k, v);
  return frame;
}

}  // namespace cmp::cells2d
