#pragma once
// Typed parameters of the shell styles, checked once when a style is built.
namespace cmp::shell {

// An isotropic elastic sheet (stretching and bending styles).
struct MaterialParameters {
  double youngs_modulus = 1.0;  // E [pressure units], > 0
  double poisson_ratio = 1.0 / 3.0;  // nu, in (-1, 0.5]
  double thickness = 1.0;       // t [length], > 0
  // The 2D stretching modulus Y = E t (thesis B.2.1).
  double stretching_modulus() const { return youngs_modulus * thickness; }
  // The bending rigidity kappa = E t^3 / (12 (1 - nu^2)) (thesis B.2.1).
  double bending_rigidity() const {
    return youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  }
};

// Throws cmp::UsageError naming the first bad value: E or t not positive and finite, nu
// outside (-1, 0.5]. `style` prefixes the message ("svk: Poisson ratio nu = 0.7 ...").
void validate(const MaterialParameters& p, const char* style);

// A constant turgor pressure.
struct PressureParameters {
  double turgor = 0.0;  // Pi [pressure units], finite (Pi > 0 inflates)
};

// Throws cmp::UsageError when Pi is not finite.
void validate(const PressureParameters& p, const char* style);

}  // namespace cmp::shell
