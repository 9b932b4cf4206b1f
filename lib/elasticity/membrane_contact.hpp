#pragma once
// An inflated spherical St Venant-Kirchhoff membrane squeezed between two rigid, frictionless,
// parallel plates (thesis B.6, Fig. B.9; Yang & Feng 1970, Feng & Yang 1973), solved by
// shooting along the meridian with GSL's ODE solvers and root finding (instead of the thesis's
// particle swarms).
//
// Geometry (upper half, by symmetry about the equatorial plane): psi in [0, pi/2] is the polar
// angle of a material point on the rest sphere (radius R0), measured from the axis; the
// deformed meridian is (rho(psi), eta(psi)), eta measured up from the equatorial plane; the
// plate is at eta = eta_bar (the half gap). Stretches (Eqs. B.90-B.91):
//   lambda_1 = sqrt(rho'^2 + eta'^2)/R0,  lambda_2 = rho/(R0 sin psi).
// SVK energy per rest area (Eq. B.92 with its weight 2 pi R0^2 sin psi restored):
//   W = E t/(8 (1 - nu^2)) [(l1^2 - 1)^2 + (l2^2 - 1)^2 + 2 nu (l1^2 - 1)(l2^2 - 1)].
// Cauchy tensions (force per deformed length), k = E t/(2 (1 - nu^2)):
//   T1 = (1/l2) dW/dl1 = k (l1/l2)(l1^2 + nu l2^2 - 1 - nu)   (B.99 prints l2/l1)
//   T2 = (1/l1) dW/dl2 = k (l2/l1)(l2^2 + nu l1^2 - 1 - nu)   (B.100)
//   f1 = dT1/dl1 = k (1/l2)(3 l1^2 + nu l2^2 - 1 - nu)         (B.101 prints 1 for the 3)
//   f2 = dT1/dl2 = k (l1/l2^2)(nu l2^2 - l1^2 + 1 + nu)        (B.102)
// Equilibrium with theta the angle of the meridian below the horizontal (d rho = R0 l1 cos
// theta d psi, d eta = -R0 l1 sin theta d psi):
//   meridional  d(rho T1)/d psi = R0 l1 T2 cos theta
//   normal      T1 d theta/d psi = R0 l1 (P - T2 sin theta/rho)
// so that, with l2' = (l1 cos theta - l2 cos psi)/sin psi (B.94/B.97),
//   l1' = [l1 cos theta (T2 - T1)/(l2 sin psi) - f2 l2'] / f1       (B.93/B.95; B.93 prints
//         f1/f3 for f3/f1 with f3 = T1 - T2).
// Contact region psi < Gamma: theta = 0, eta = eta_bar (the plate's reaction balances P, the
// contact pressure equals P). Free region psi > Gamma: all of the above. At psi = Gamma the
// tangent, rho, l1 and l2 are continuous (no bending, no friction). The volume is
// V = 2 int pi rho^2 |d eta| over the free region (B.104).
// Conditions: l1 = l2 = l0 at the pole; theta = pi/2 (omega = dDelta/dpsi = 0) and eta = 0 at
// the equator psi = pi/2; and either V = V_i (constant volume: an incompressible fill, the
// case of Ch. 5 and Fig. B.9; unknowns Gamma, l0, P) or P = P_i (constant pressure; unknowns
// Gamma, l0). P_i and the inflated radius R_i = l_i R0 come from the free SVK sphere
// (pressurised_sphere.hpp, the corrected B.81; the thesis takes l_i from the printed B.82).
//
// Outputs follow B.106: the plate force F = P pi r_c^2 with r_c = R0 l2(Gamma) sin Gamma.
// Vertical balance of the part above any horizontal cut gives a first integral,
//   P pi rho^2 - 2 pi rho T1 sin theta = F,
// which at the equator (theta = pi/2) is an independent check of the solution (equator_force);
// so is virtual work: dU = -2 F d eta_bar + P dV for the elastic energy U.
// Normalisation (the thesis does not define X^ and F^): compression X = 1 - eta_bar/R_i, force
// F^ = F/(E t R0), pressure P* = P/P_i (Fig. B.9a).
// Units: lengths [length], P and E [pressure], F [force], tensions [force/length].
#include "elasticity/sheet.hpp"

#include <vector>

namespace cmp::elasticity {

enum class Fill {
  ConstantVolume,    // incompressible fill: V = V_i, P is solved for
  ConstantPressure,  // P = P_i, V follows
};

// One solved compression (all in the caller's units).
struct MembraneContact {
  double compression = 0;     // X = 1 - eta_bar/R_i
  double half_gap = 0;        // eta_bar, plate to equatorial plane [length]
  double contact_angle = 0;   // Gamma [rad], rest polar angle of the contact edge
  double pole_stretch = 0;    // l0, both stretches at the pole
  double pressure = 0;        // P [pressure]
  double contact_radius = 0;  // r_c [length]
  double equator_radius = 0;  // rho_bar, radius at the equatorial plane [length]
  double equator_tension = 0; // T1 at the equator [force/length]
  double force = 0;           // F = P pi r_c^2 [force], on each plate
  double equator_force = 0;   // P pi rho_bar^2 - 2 pi rho_bar T1(equator): equals F at a solution
  double volume = 0;          // enclosed volume [length^3]
  double energy = 0;          // elastic (SVK) energy of the whole membrane [force x length]
  double residual = 0;        // largest |condition| left by the root finder (dimensionless)
};

// A point of the deformed upper meridian.
struct MeridianPoint {
  double psi = 0;                       // rest polar angle [rad]
  double rho = 0, eta = 0;              // deformed radius and height [length]
  double theta = 0;                     // meridian angle below the horizontal [rad]
  double lambda1 = 0, lambda2 = 0;      // principal stretches
  double tension1 = 0, tension2 = 0;    // Cauchy tensions [force/length]
  double vertical_force = 0;            // P pi rho^2 - 2 pi rho T1 sin theta [force]: = F on the free part (psi >= Gamma)
};

struct MembraneContactOptions {
  double ode_tolerance = 1e-11;   // relative and absolute error per step of the RK8(9) integrator
  double root_tolerance = 1e-10;  // on the dimensionless conditions
  int max_iterations = 100;       // of the hybrid root finder per compression
  double max_step = 0.01;         // largest compression step of the continuation in sweep()
};

class InflatedMembrane {
 public:
  // The membrane (sheet, rest radius R0 > 0) inflated by the pressure P_i > 0. Throws
  // cmp::UsageError for bad values (validate(sheet), R0 or P_i not positive and finite).
  InflatedMembrane(const Sheet& sheet, double rest_radius, double inflation_pressure,
                   MembraneContactOptions options = {});

  double inflation_pressure() const { return p_i_; }
  double inflated_stretch() const { return l_i_; }      // l_i (the free SVK sphere)
  double inflated_radius() const { return l_i_ * r0_; } // R_i
  double inflated_volume() const;                       // V_i = (4/3) pi R_i^3
  double force_scale() const;                           // E t R0, the unit of F^

  // The free inflated sphere (X = 0, Gamma = 0, F = 0).
  MembraneContact free_state() const;

  // Solves compressions X (each in (0, 1), increasing) by continuation from the free sphere
  // with steps of at most options.max_step. Throws cmp::ComputationError (naming X) when the
  // root finder fails even after halving the step.
  std::vector<MembraneContact> sweep(const std::vector<double>& compressions, Fill fill) const;

  // One compression X from a solved state nearby (a previous result of sweep() or solve()).
  // Throws cmp::ComputationError when the root finder does not converge.
  MembraneContact solve(double compression, Fill fill, const MembraneContact& guess) const;

  // The upper meridian of a solved state at n + 1 rest angles evenly spaced in [0, pi/2]
  // (n >= 1), integrated again from the state's Gamma, l0 and P.
  std::vector<MeridianPoint> meridian(const MembraneContact& state, int n) const;

 private:
  Sheet sheet_;
  double r0_, p_i_, l_i_;
  MembraneContactOptions options_;
};

}  // namespace cmp::elasticity
