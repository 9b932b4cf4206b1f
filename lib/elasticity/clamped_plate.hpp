#pragma once
// A circular plate of radius R0, clamped at its edge (w = 0 and dw/dr = 0 at r = R0), loaded
// normally (thesis B.5.3-B.5.4, Figs. B.5-B.7). D = E t^3/(12 (1 - nu^2)) (Sheet::
// bending_rigidity). Units: lengths [length], a point load P0 [force], a uniform load q
// [pressure = force/area], deflections w [length].
//
// Linear (Kirchhoff) plate theory, small deflection:
//   point load at the centre  w(r) = P0/(16 pi D) (2 r^2 ln(r/R0) + R0^2 - r^2)   (Eq. B.84,
//                             printed with "2 r^2" beside "R": the radius is r throughout),
//                             w_max = w(0) = P0 R0^2/(16 pi D)                     (Eq. B.85);
//   uniform load q            w(r) = q (R0^2 - r^2)^2/(64 D),  w_max = q R0^4/(64 D) (B.86-B.87).
// These hold while w_max is small against t: within about 10 % for w_max < t/2 (B.5.4), the
// regime of *_linear_limit below. Fig. B.5's point load (5e3 N on R0 = 2.25, t = 0.1, E = 25e6,
// nu = 1/3) gives w_max = 0.215 = 2.15 t, far outside it; Fig. B.6's 1e3 N read as a total load
// (q = 1e3/(pi R0^2) = 62.9 Pa) gives w_max = 0.0107 = 0.107 t, inside it.
//
// Large deflection, uniform load (approximate energy solution, Eq. B.88 with R^3 -> R0^4 and
// E -> E t so that both terms are pressures):
//   q = 64 D w_max/R0^4 + (8/3) (E t/(1 - nu)) w_max^3/R0^4,
// i.e. with P* = (q/E)(R0/t)^4 and w = w_max/t:
//   (12 (1 - nu^2)/64) P* = w (1 + (1 + nu)/2 w^2).
// The printed Eq. B.89 puts (1 - nu^2) in the denominator of the left side; that agrees with
// B.88 only at nu = 0 (Fig. B.7's value). The linear term is the bending solution, the cubic
// one the membrane (stretching) solution (the text after B.89 names them the other way round).
#include "elasticity/sheet.hpp"

namespace cmp::elasticity {

// Eq. B.84: the deflection at distance r in [0, R0] from the centre under a central point load
// P0 (w(0) = w_max; the logarithmic term is taken as 0 at r = 0). Throws std::domain_error for
// r outside [0, R0].
double point_load_deflection(const Sheet& sheet, double plate_radius, double load, double r);
// Eq. B.85.
double point_load_max_deflection(const Sheet& sheet, double plate_radius, double load);
// The central point load whose linear w_max is t/2 (16 pi D t/(2 R0^2)): the linear theory
// holds below it.
double point_load_linear_limit(const Sheet& sheet, double plate_radius);

// Eq. B.86 for a uniform load q [pressure]; same domain as point_load_deflection.
double uniform_load_deflection(const Sheet& sheet, double plate_radius, double pressure, double r);
// Eq. B.87.
double uniform_load_max_deflection(const Sheet& sheet, double plate_radius, double pressure);
// The uniform load whose linear w_max is t/2 (64 D t/(2 R0^4)).
double uniform_load_linear_limit(const Sheet& sheet, double plate_radius);

// The dimensionless load P* = (q/E)(R0/t)^4 of Fig. B.7 and back.
double plate_load_star(const Sheet& sheet, double plate_radius, double pressure);
double plate_pressure_from_star(const Sheet& sheet, double plate_radius, double load_star);

// The corrected B.89: P* as a function of w_max/t (nu from the sheet; E, t, R0 drop out).
double large_deflection_load_star(double poisson_ratio, double deflection_over_thickness);
// Its inverse: w_max/t for a given P* >= 0, the unique real root of the monotone cubic (GSL
// Brent bracketing, relative accuracy 1e-12). Throws std::domain_error for P* < 0 or not
// finite, std::domain_error for nu outside (-1, 0.5].
double large_deflection_max_deflection(double poisson_ratio, double load_star);

}  // namespace cmp::elasticity
