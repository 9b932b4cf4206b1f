#include "cells2d/packing_analysis.hpp"

#include "packing/rattlers.hpp"

#include <numbers>
#include <utility>

namespace cmp::cells2d {

double PackingAnalysis::lobe_pressure(const std::vector<Cell>& cells, int lobe) const {
  const double d = lobe_diameter(cells[static_cast<std::size_t>(lobe >> 1)], lobe & 1);
  return d > 0 ? lobe_force[static_cast<std::size_t>(lobe)] / (std::numbers::pi * d) : 0.0;
}

std::vector<double> bud_pressures(const std::vector<Cell>& cells, ContactEngine& engine) {
  std::vector<double> force(cells.size(), 0.0);
  engine.for_each_contact(cells, [&](const Contact& c) {
    if (c.overlap <= 0) return;  // within an attractive law's reach, not touching
    if (c.a & 1) force[static_cast<std::size_t>(c.a >> 1)] += c.force;
    if (c.b & 1) force[static_cast<std::size_t>(c.b >> 1)] += c.force;
  });
  for (std::size_t i = 0; i < cells.size(); ++i)
    force[i] = cells[i].bud > 0 ? force[i] / (std::numbers::pi * cells[i].bud) : 0.0;
  return force;
}

PackingAnalysis analyse_packing(const std::vector<Cell>& cells, ContactEngine& engine) {
  PackingAnalysis a;
  const std::size_t n = cells.size();
  a.cells = static_cast<int>(n);
  const Domain& box = engine.domain();
  a.area_fraction = total_area(cells) / (box.lx * box.ly);
  a.lobe_contacts.assign(2 * n, 0);
  a.lobe_force.assign(2 * n, 0.0);
  std::vector<std::pair<int, int>> pairs;
  engine.for_each_contact(cells, [&](const Contact& c) {
    a.energy += engine.pair_energy(c.overlap);
    if (c.overlap <= 0) return;  // within an attractive law's reach, not touching
    const Eigen::Vector2d f = c.force / c.distance * c.d;
    a.pressure_tensor += c.d * f.transpose();
    ++a.lobe_contacts[static_cast<std::size_t>(c.a)], ++a.lobe_contacts[static_cast<std::size_t>(c.b)];
    a.lobe_force[static_cast<std::size_t>(c.a)] += c.force, a.lobe_force[static_cast<std::size_t>(c.b)] += c.force;
    pairs.emplace_back(c.a, c.b);
  });
  a.pressure_tensor /= box.lx * box.ly;
  a.pressure = 0.5 * a.pressure_tensor.trace();
  a.contacts = static_cast<int>(pairs.size());
  double rate_area = 0, area = 0;
  for (const Cell& c : cells) rate_area += cell_area(c.bud) * c.rate, area += cell_area(c.bud);
  a.mean_rate = area > 0 ? rate_area / area : 0.0;

  // Rattlers (the rule of packing_analysis.hpp), removed until none is left.
  auto pruned = packing::prune_rattlers(a.cells, 2, pairs, [](std::span<const int> live) {
    const int total = live[0] + live[1];
    return total < 3 || (total == 3 && live[0] > 0 && live[1] > 0);
  });
  a.rattler = std::move(pruned.rattler);
  const std::vector<int>& live = pruned.live;  // contacts with non-rattlers
  for (std::size_t i = 0; i < n; ++i) {
    if (a.rattler[i]) { ++a.rattlers; continue; }
    a.unconstrained += (live[2 * i] == 0) + (live[2 * i + 1] == 0);
  }
  for (const auto& [p, q] : pairs)
    if (!a.rattler[static_cast<std::size_t>(p >> 1)] && !a.rattler[static_cast<std::size_t>(q >> 1)]) ++a.network_contacts;
  const int stable = a.cells - a.rattlers;
  if (stable > 0) {
    a.Z = 2.0 * a.network_contacts / stable;
    a.f_u = static_cast<double>(a.unconstrained) / stable;
    a.Z_iso = 6 - 2 * a.f_u - 2.0 / stable;
  }
  return a;
}

}  // namespace cmp::cells2d
