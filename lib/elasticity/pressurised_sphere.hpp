#pragma once
// A spherical St Venant-Kirchhoff membrane of rest radius R0 inflated by a pressure
// difference dP (thesis B.5.1, Fig. B.4A). Uniform stretch lambda = R/R0, Green strain
// (lambda^2 - 1)/2 in both directions, energy per rest area (Eq. B.80)
//   W(lambda) = E t (lambda^2 - 1)^2 / (4 (1 - nu)).
// Equilibrium: stationarity of 4 pi R0^2 W(lambda) - dP (4/3) pi R0^3 lambda^3, or Laplace's law
// dP = 2 T/(lambda R0) with the Cauchy tension T = E t (lambda^2 - 1)/(2 (1 - nu)), gives
//   dP = E t (lambda^2 - 1) / ((1 - nu) R0 lambda)                         (corrected B.81)
// whose inverse is closed: with c = dP R0 (1 - nu)/(E t), lambda = (c + sqrt(c^2 + 4))/2.
// The printed B.81, dP = E t (lambda^3 - lambda)/((1 - nu) R0), is lambda^2 times this and is
// not the equilibrium of B.80; B.82 is the printed B.81 written in eps_r = lambda - 1.
// Membrane theory (no bending): valid for dP >= 0 and R0 >> t; the closed inverse exists for
// any real dP, but a membrane under dP < 0 would wrinkle or buckle (see buckling.hpp).
// Units: dP [pressure], R0 [length], E [pressure], t [length]; lambda and eps_r dimensionless.
#include "elasticity/sheet.hpp"

namespace cmp::elasticity {

// The corrected equilibrium pressure dP(lambda) above. lambda > 0.
double sphere_pressure(const Sheet& sheet, double rest_radius, double stretch);

// Its inverse, the equilibrium stretch lambda(dP) (closed form above); lambda - 1 is the
// radial engineering strain eps_r that the thesis measures as cbrt(V/V0) - 1.
double sphere_stretch(const Sheet& sheet, double rest_radius, double pressure);

// The printed Eq. B.81, dP = E t (lambda^3 - lambda)/((1 - nu) R0), for comparison only.
double sphere_pressure_printed(const Sheet& sheet, double rest_radius, double stretch);

// The printed Eq. B.82 solved for eps_r (the real root of eps + 3/2 eps^2 + 1/2 eps^3 =
// dP R0 (1 - nu)/(2 E t), i.e. the inverse of the printed B.81), for comparison only.
double sphere_strain_printed(const Sheet& sheet, double rest_radius, double pressure);

// The infinitesimal-strain limit of both: eps_r = dP R0 (1 - nu)/(2 E t).
double sphere_strain_linear(const Sheet& sheet, double rest_radius, double pressure);

// The Cauchy tension (force per deformed length) T = E t (lambda^2 - 1)/(2 (1 - nu)) of the
// uniformly stretched membrane.
double sphere_tension(const Sheet& sheet, double stretch);

}  // namespace cmp::elasticity
