#pragma once
// A thin isotropic elastic sheet, the material of every analytic benchmark of Appendix B
// (B.5-B.7), and the small helpers every benchmark shares. Units are whatever the caller uses
// consistently (SI in the thesis: Pa, m, N); nothing here assumes a unit.
namespace cmp::elasticity {

struct Sheet {
  double youngs_modulus = 1.0;       // E [pressure], > 0
  double poisson_ratio = 1.0 / 3.0;  // nu, in (-1, 0.5] (0.5 is the Chapter 5 value)
  double thickness = 1.0;            // t [length], > 0
  // The 2D stretching modulus Y = E t [force/length] (thesis B.2.1).
  double stretching_modulus() const { return youngs_modulus * thickness; }
  // The bending rigidity (flexural rigidity of plate theory) D = kappa = E t^3/(12(1-nu^2))
  // [force x length] (thesis B.2.1, B.5.3, B.7).
  double bending_rigidity() const {
    return youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  }
};

// Throws cmp::UsageError naming the first bad value (E or t not positive and finite, nu
// outside (-1, 0.5]); `who` prefixes the message.
void validate(const Sheet& sheet, const char* who);

// The Poisson ratio measured on a uniaxially stretched sheet from its axial strain eps_axial
// (along the pull) and transverse strain eps_transverse: nu = -eps_transverse / eps_axial.
// (Eq. B.83 prints the inverse ratio, -eps_1/eps_2.) Throws cmp::ComputationError when
// eps_axial is 0 or either strain is not finite.
double poisson_ratio_from_strains(double eps_axial, double eps_transverse);

}  // namespace cmp::elasticity
