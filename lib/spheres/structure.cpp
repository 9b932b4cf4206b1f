#include "spheres/structure.hpp"

#include "core/errors.hpp"
#include "neighbours/cell_grid.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/rattlers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace cmp::spheres {

namespace {

// Unordered pairs of p per bin of width bin_width * d up to bins * bin_width * d, counting
// every periodic image when that reach exceeds half the box (small packings).
std::vector<long> pair_histogram(const SpherePacking& p, double bin_width, int bins) {
  const int n = p.size();
  const double d = p.mean_diameter(), reach = bins * bin_width * d;
  std::vector<long> counts(static_cast<std::size_t>(bins), 0);
  auto add = [&](double r) {
    // Compared as a double first: a huge (or NaN) distance is no int.
    const double b = r / d / bin_width;
    if (b < bins) ++counts[static_cast<int>(b)];
  };
  neighbours::Box box;
  box.lengths = p.box;
  box.periodic = {true, true, true};
  if (reach <= p.box.minCoeff() / 2) {
    neighbours::CellGrid grid(box, reach);
    grid.build(p.positions);
    grid.for_each_pair(p.positions, [&](int, int, const Eigen::Vector3d&, double r2) { add(std::sqrt(r2)); });
    return counts;
  }
  // Every image within reach: ordered pairs (i, j, shift) except i = j unshifted, halved.
  Eigen::Vector3i images;
  for (int a = 0; a < 3; ++a) {
    if (!(reach / p.box[a] <= kMaxRdfImages))
      throw UsageError(fmt::format("g(r) range reaches {:.3g} box lengths, more than {}: lower --rmax", reach / p.box[a],
                                   kMaxRdfImages));
    images[a] = static_cast<int>(std::ceil(reach / p.box[a])) + 1;
  }
  std::vector<long> ordered(static_cast<std::size_t>(bins), 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d d0 = box.minimum_image(p.positions.row(i).transpose() - p.positions.row(j).transpose());
      for (int sx = -images[0]; sx <= images[0]; ++sx)
        for (int sy = -images[1]; sy <= images[1]; ++sy)
          for (int sz = -images[2]; sz <= images[2]; ++sz) {
            if (i == j && sx == 0 && sy == 0 && sz == 0) continue;
            const double r = (d0 + Eigen::Vector3d(sx * p.box[0], sy * p.box[1], sz * p.box[2])).norm();
            const double b = r / d / bin_width;
            if (b < bins) ++ordered[static_cast<int>(b)];
          }
    }
  for (int b = 0; b < bins; ++b) counts[b] = ordered[b] / 2;
  return counts;
}

}  // namespace

RadialDistribution radial_distribution(const std::vector<SpherePacking>& packings, double bin_width, double r_max) {
  if (!(bin_width > 0)) throw UsageError("g(r) bin width must be positive");
  if (!(r_max > bin_width)) throw UsageError("g(r) range must exceed one bin");
  // Checked as a double before it becomes an int (the options check it first, naming them).
  if (!(r_max / bin_width <= kMaxRdfBins))
    throw UsageError(fmt::format("g(r) range over bin width makes more than {} bins", kMaxRdfBins));
  const int bins = static_cast<int>(std::floor(r_max / bin_width + 1e-9));
  RadialDistribution rdf;
  rdf.bin_width = bin_width;
  rdf.r.resize(static_cast<std::size_t>(bins));
  rdf.g.assign(static_cast<std::size_t>(bins), 0.0);
  rdf.pair_counts.assign(static_cast<std::size_t>(bins), 0);
  for (int b = 0; b < bins; ++b) rdf.r[b] = (b + 0.5) * bin_width;
  for (const auto& p : packings) {
    const int n = p.size();
    if (n < 2) continue;
    const auto counts = pair_histogram(p, bin_width, bins);
    const double d = p.mean_diameter();
    const double pairs = 0.5 * n * (n - 1.0), volume = p.box_volume() / (d * d * d);
    for (int b = 0; b < bins; ++b) {
      const double r0 = b * bin_width, r1 = r0 + bin_width;
      const double shell = 4.0 / 3.0 * std::numbers::pi * (r1 * r1 * r1 - r0 * r0 * r0);
      rdf.g[b] += counts[b] / (pairs * shell / volume) / static_cast<double>(packings.size());
      rdf.pair_counts[b] += counts[b];
    }
  }
  return rdf;
}

ContactStatistics contact_statistics(const SpherePacking& packing, const HertzMaterial& material) {
  ContactStatistics s;
  s.spheres = packing.size();
  s.volume_fraction = packing.volume_fraction();
  if (s.spheres == 0) return s;
  HertzSpheres system(packing.box, packing.radii, material, 0.0);
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(packing.positions.data(), 3L * s.spheres);
  const auto state = system.evaluate(x);
  const double d = packing.mean_diameter();
  s.contacts = static_cast<int>(state.contacts.size());
  s.contact_number = 2.0 * s.contacts / s.spheres;
  s.pressure = state.pressure;
  const auto rattler = find_rattlers(s.spheres, state.contacts);
  s.rattlers = static_cast<int>(std::count(rattler.begin(), rattler.end(), true));
  int load_bearing_contacts = 0;
  for (const auto& c : state.contacts) {
    s.forces.push_back(c.force / (material.youngs_modulus * d * d));
    s.max_overlap = std::max(s.max_overlap, c.overlap / d);
    load_bearing_contacts += !rattler[c.i] && !rattler[c.j];
  }
  if (s.rattlers < s.spheres) s.contact_number_without_rattlers = 2.0 * load_bearing_contacts / (s.spheres - s.rattlers);
  if (!s.forces.empty()) {
    s.mean_force = std::accumulate(s.forces.begin(), s.forces.end(), 0.0) / s.forces.size();
    s.force_cv = coefficient_of_variation(s.forces);
  }
  return s;
}

double coefficient_of_variation(const std::vector<double>& values) {
  if (values.empty()) return 0;
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  double var = 0;
  for (double v : values) var += (v - mean) * (v - mean);
  return std::sqrt(var / values.size()) / mean;
}

Histogram normalised_histogram(const std::vector<double>& values, int bins, double max_ratio) {
  Histogram h;
  if (bins < 1 || !(max_ratio > 0)) throw UsageError("histogram needs bins >= 1 and a positive range");
  h.centres.resize(static_cast<std::size_t>(bins));
  h.density.assign(static_cast<std::size_t>(bins), 0.0);
  const double width = max_ratio / bins;
  for (int b = 0; b < bins; ++b) h.centres[b] = (b + 0.5) * width;
  if (values.empty()) return h;
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  if (!(mean > 0)) return h;
  for (double v : values) {
    const int b = static_cast<int>(v / mean / width);
    if (b >= 0 && b < bins) h.density[b] += 1.0 / (values.size() * width);
  }
  return h;
}

}  // namespace cmp::spheres

