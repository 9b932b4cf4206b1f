#include "elasticity/pressurised_sphere.hpp"

#include <gsl/gsl_poly.h>

#include <cmath>
#include <stdexcept>

namespace cmp::elasticity {

namespace {
// c = dP R0 (1 - nu)/(E t), the dimensionless load of every relation here.
double load(const Sheet& s, double R0, double dP) { return dP * R0 * (1.0 - s.poisson_ratio) / s.stretching_modulus(); }
}  // namespace

double sphere_pressure(const Sheet& s, double R0, double lambda) {
  if (!(lambda > 0)) throw std::domain_error("sphere_pressure: the stretch must be positive");
  return s.stretching_modulus() * (lambda * lambda - 1.0) / ((1.0 - s.poisson_ratio) * R0 * lambda);
}

double sphere_stretch(const Sheet& s, double R0, double dP) {
  // lambda^2 - c lambda - 1 = 0, the positive root, written without cancellation for c < 0.
  const double c = load(s, R0, dP), r = std::sqrt(c * c + 4.0);
  return c >= 0 ? 0.5 * (c + r) : 2.0 / (r - c);
}

double sphere_pressure_printed(const Sheet& s, double R0, double lambda) {
  return s.stretching_modulus() * (lambda * lambda * lambda - lambda) / ((1.0 - s.poisson_ratio) * R0);
}

double sphere_strain_printed(const Sheet& s, double R0, double dP) {
  // eps^3/2 + 3 eps^2/2 + eps - c/2 = 0, i.e. eps^3 + 3 eps^2 + 2 eps - c = 0: monotone for
  // eps > -1 + 1/sqrt(3); take the largest real root (the branch through eps = 0 at c = 0).
  const double c = load(s, R0, dP);
  double r[3];
  const int n = gsl_poly_solve_cubic(3.0, 2.0, -c, &r[0], &r[1], &r[2]);
  return r[n - 1];
}

double sphere_strain_linear(const Sheet& s, double R0, double dP) { return 0.5 * load(s, R0, dP); }

double sphere_tension(const Sheet& s, double lambda) {
  return s.stretching_modulus() * (lambda * lambda - 1.0) / (2.0 * (1.0 - s.poisson_ratio));
}

}  // namespace cmp::elasticity
