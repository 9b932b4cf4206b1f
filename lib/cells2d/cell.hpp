#pragma once
// A budding cell of the 2D cell model (thesis 3.4.1, S2.10-S2.13): two rigidly attached,
// tangent disks, the mother of diameter sigma and the bud of diameter sigma_b in [0, sigma].
// Lengths are in units of the mother diameter sigma = 1 throughout lib/cells2d.
//
// Geometry (the only one the thesis's moment of inertia fits): the lobe centres are
// (1 + Delta) sigma / 2 apart, Delta = sigma_b / sigma, and the cell position r is the centre
// of mass of the two disks (mass proportional to area). With e = (cos theta, sin theta):
//   mother = r + d Delta^2 / (1 + Delta^2) e,   bud = r - d / (1 + Delta^2) e,   d = (1 + Delta) / 2,
// so theta points from the bud to the mother. Shared by every model of budding cells (the
// periodic box of Chapter 3 and the chamber of Chapter 2).
#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <vector>

namespace cmp::cells2d {

struct Cell {
  double x = 0, y = 0;     // centre of mass [sigma]
  double theta = 0;        // orientation [rad], from the bud towards the mother
  double bud = 0;          // bud diameter sigma_b [sigma], in [0, 1]
  double rate0 = 1;        // growth rate without feedback gamma_i^0 [gamma^0]
  double rate = 1;         // current growth rate gamma_i [gamma^0]
};

// Cell area a = (pi/4)(1 + sigma_b^2) [sigma^2].
inline double cell_area(double bud) { return 0.25 * std::numbers::pi * (1 + bud * bud); }
// The bud diameter of a cell of area a, clamped to [0, 1] (a in [pi/4, pi/2] gives no clamp).
inline double bud_for_area(double area) {
  const double b2 = 4 * area / std::numbers::pi - 1;
  return b2 <= 0 ? 0.0 : (b2 >= 1 ? 1.0 : std::sqrt(b2));
}
// Area of a cell that is about to divide (bud = mother): pi/2 [sigma^2].
inline constexpr double kDivisionArea = 0.5 * std::numbers::pi;

// I/M of the two disks about the centre of mass [sigma^2] (thesis 3.4.1):
//   (1/8)[(1 + D^4)/(1 + D^2) + 2((1 + D) D / (1 + D^2))^2],  D = sigma_b.
inline double inertia_per_mass(double bud) {
  const double d2 = bud * bud, q = (1 + bud) * bud / (1 + d2);
  return 0.125 * ((1 + d2 * d2) / (1 + d2) + 2 * q * q);
}

// Offsets of the mother and bud centres from the centre of mass along e [sigma]:
// mother at +mother_offset, bud at -bud_offset.
inline double mother_offset(double bud) { return 0.5 * (1 + bud) * bud * bud / (1 + bud * bud); }
inline double bud_offset(double bud) { return 0.5 * (1 + bud) / (1 + bud * bud); }

// Lobe index convention: lobe 2i is the mother of cell i, lobe 2i + 1 its bud.
inline double lobe_diameter(const Cell& c, int lobe) { return lobe == 0 ? 1.0 : c.bud; }
// Centre of lobe (0 mother, 1 bud) of a cell [sigma].
inline Eigen::Vector2d lobe_centre(const Cell& c, int lobe) {
  const Eigen::Vector2d e(std::cos(c.theta), std::sin(c.theta));
  const double s = lobe == 0 ? mother_offset(c.bud) : -bud_offset(c.bud);
  return Eigen::Vector2d(c.x, c.y) + s * e;
}

// Total area of the cells [sigma^2] and the area fraction in a box of side L [sigma].
double total_area(const std::vector<Cell>& cells);
inline double area_fraction(const std::vector<Cell>& cells, double box) { return total_area(cells) / (box * box); }

// The cell whose mother and bud lobes have these centres and the bud this diameter (the
// inverse of lobe_centre): the centre of mass and the angle of mother - bud.
Cell cell_from_lobes(const Eigen::Vector2d& mother, const Eigen::Vector2d& bud_centre, double bud);

}  // namespace cmp::cells2d
