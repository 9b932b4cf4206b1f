#pragma once
// Structure of sphere packings (thesis Ch. 4, Fig. 4.3): the radial
// distribution function of centres, contact numbers, rattlers and contact forces.
#include "forcefield/hertz.hpp"
#include "spheres/sphere_packing.hpp"

#include <vector>

namespace cmp::spheres {

struct RadialDistribution {
  double bin_width = 0;         // in units of the mean diameter
  std::vector<double> r;        // bin centres, in mean diameters
  std::vector<double> g;        // rho(r) / rho_0: 1 for an ideal gas
  std::vector<long> pair_counts;  // unordered pairs per bin, summed over packings
};

// g(r) of centres over one or several packings (pooled), r in units of each packing's mean
// diameter, up to r_max (in diameters). Normalised per packing to the ideal gas of the same
// density, g = pairs / (N (N - 1) / 2 * shell volume / V), averaged over packings. Up to half
// the box: O(N) per packing by linked cells. Beyond (small boxes, e.g. N = 50 where L/2 is
// 1.5 diameters) every periodic image is counted, O(N^2 (r_max / L)^3), and own images add
// about 1/N to g. Throws cmp::UsageError for bin_width <= 0 or r_max <= bin_width.
// The most bins of a g(r) (r_max / bin_width), and the most box lengths its range may reach
// (the image sum is cubic in it): beyond, cmp::UsageError (shellpack checks its options first).
inline constexpr double kMaxRdfBins = 1e6;
inline constexpr double kMaxRdfImages = 20;
RadialDistribution radial_distribution(const std::vector<SpherePacking>& packings, double bin_width = 0.01,
                                       double r_max = 3.0);

struct ContactStatistics {
  int spheres = 0;
  int contacts = 0;              // touching pairs (overlap > 0)
  double contact_number = 0;     // Z = 2 contacts / N (rattlers included, as Z = 6 - 4/N)
  int rattlers = 0;              // iterative removal of spheres with < 4 contacts
  double contact_number_without_rattlers = 0;  // Z over the load-bearing spheres
  double pressure = 0;           // virial, units of E
  double volume_fraction = 0;
  std::vector<double> forces;    // Hertz force of every contact, in units of E * d^2 (d = mean diameter)
  double mean_force = 0, force_cv = 0;  // and its coefficient of variation sigma/mean
  double max_overlap = 0;        // in units of the mean diameter
};

// Contacts, Z, rattlers and contact forces of one packing under the Hertz law of `material`.
ContactStatistics contact_statistics(const SpherePacking& packing, const HertzMaterial& material = {});

// Population standard deviation over the mean (0 for no values).
double coefficient_of_variation(const std::vector<double>& values);

// Histogram of values / mean over [0, max_ratio) in `bins` bins, as a probability density
// (integrates to the fraction of values inside the range).
struct Histogram {
  std::vector<double> centres, density;
};
Histogram normalised_histogram(const std::vector<double>& values, int bins = 40, double max_ratio = 4.0);

}  // namespace cmp::spheres
