#pragma once
// Buckling of a spherical shell of radius R0 under external pressure (thesis B.7, Fig. B.10),
// and the calibrations that give a spring-and-hinge mesh its continuum moduli Y and kappa.
//   p_c = 4 sqrt(kappa Y)/R0^2  (the classical result; Eq. B.107 prints 4 sqrt(kappa Y/R0^2),
//         which is not a pressure)
//       = 4 Y/(R0 sqrt(gamma)) = 2 E (t/R0)^2/sqrt(3 (1 - nu^2)) for a continuum sheet,
//   gamma = Y R0^2/kappa, the Foppl-von Karman number (Eq. B.17) = 12 (1 - nu^2)(R0/t)^2.
// Units: Y [force/length], kappa [force x length], R0 [length], p_c [pressure]; gamma is
// dimensionless. Reference: p_c R0/Y = 0.12649, 0.05657, 0.04000, 0.01789 at gamma = 1e3, 5e3,
// 1e4, 5e4 (R0/t = 9.682, 21.651, 30.619, 68.465 at nu = 1/3).
//
// Mesh calibrations (triangulated sheets of equilateral triangles):
//  * harmonic springs of constant k (energy k/2 (l - l0)^2 per edge) make a sheet with
//    Y = 2 k/sqrt(3) and nu = 1/3 (Seung-Nelson; the springs-seung-nelson style of lib/shell
//    sets k = sqrt(3) E t/2);
//  * normal-vector springs kappa~ sum (1 - n_a . n_b) over the hinges (B.35) on a sheet of
//    equilateral triangles bent with its vertices on a smooth surface store, per area,
//      (kappa/2)(c1 + c2)^2 + kappa_G c1 c2,  kappa = (sqrt(3)/2) kappa~,  kappa_G = -(2/sqrt(3)) kappa~
//    (measured in tests/elasticity/test_hinge_calibration.cpp on a flat disc mapped onto
//    cylinders of both orientations, a sphere and a saddle). So the mechanical bending rigidity
//    is the Cylinder calibration of B.36 (Seung-Nelson; Paulose et al. use it with Y = 2k/sqrt(3)),
//    and lib/shell's hinge-uniform style, which sets kappa~ = 2 kappa/sqrt(3), bends like kappa.
//    A closed sphere stores 8 pi kappa~/(2 sqrt(3)) (the Gaussian term adds a constant): the
//    Sphere calibration, kappa = kappa~/(2 sqrt(3)), reproduces the sphere's total energy only.
//    lib/shell's default hinge style (kappa_e = 3 |e|^2 kappa/A_e = 2 sqrt(3) kappa on
//    equilateral triangles) is calibrated the Sphere way (it stores 8 pi kappa on icosahedral
//    spheres): its mechanical bending rigidity is 3 kappa.
#include "elasticity/sheet.hpp"

namespace cmp::elasticity {

// p_c = 4 sqrt(kappa Y)/R0^2 from the moduli (Y > 0, kappa > 0, R0 > 0).
double buckling_pressure(double stretching_modulus, double bending_rigidity, double radius);
// The same for a continuum sheet (Y = E t, kappa = E t^3/(12 (1 - nu^2))).
double buckling_pressure(const Sheet& sheet, double radius);

// gamma = Y R0^2/kappa.
double foppl_von_karman(double stretching_modulus, double bending_rigidity, double radius);
double foppl_von_karman(const Sheet& sheet, double radius);
// R0/t of a continuum sheet with Foppl-von Karman number gamma: sqrt(gamma/(12 (1 - nu^2))).
double radius_over_thickness(double foppl_von_karman_number, double poisson_ratio);

// Springs: Y = 2 k/sqrt(3) and k = sqrt(3) Y/2.
double spring_stretching_modulus(double spring_constant);
double spring_constant(double stretching_modulus);

// How a hinge constant kappa~ of normal-vector springs maps to a continuum kappa.
enum class HingeCalibration {
  Cylinder,  // kappa = (sqrt(3)/2) kappa~: the bending rigidity (mechanics)
  Sphere,    // kappa = kappa~/(2 sqrt(3)): a closed sphere's total energy 8 pi kappa
};
// kappa from kappa~ and back (kappa~ > 0; throws std::domain_error otherwise).
double hinge_bending_rigidity(double hinge_constant, HingeCalibration calibration);
double hinge_constant(double bending_rigidity, HingeCalibration calibration);
// The Gaussian modulus of normal-vector hinges, kappa_G = -(2/sqrt(3)) kappa~.
double hinge_gaussian_modulus(double hinge_constant);

}  // namespace cmp::elasticity
