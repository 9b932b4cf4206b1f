#include "elasticity/clamped_plate.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace cmp::elasticity {

namespace {
void check_radius(double r, double R0, const char* who) {
  if (!(r >= 0 && r <= R0)) throw std::domain_error(std::string(who) + ": r must be in [0, R0]");
}
void check_nu(double nu) {
  if (!(nu > -1.0 && nu <= 0.5)) throw std::domain_error("large deflection: nu must be in (-1, 0.5]");
}
}  // namespace

double point_load_deflection(const Sheet& s, double R0, double P0, double r) {
  check_radius(r, R0, "point_load_deflection");
  const double log_term = r > 0 ? 2.0 * r * r * std::log(r / R0) : 0.0;
  return P0 / (16.0 * M_PI * s.bending_rigidity()) * (log_term + R0 * R0 - r * r);
}

double point_load_max_deflection(const Sheet& s, double R0, double P0) {
  return P0 * R0 * R0 / (16.0 * M_PI * s.bending_rigidity());
}

double point_load_linear_limit(const Sheet& s, double R0) {
  return 16.0 * M_PI * s.bending_rigidity() * (0.5 * s.thickness) / (R0 * R0);
}

double uniform_load_deflection(const Sheet& s, double R0, double q, double r) {
  check_radius(r, R0, "uniform_load_deflection");
  const double d = R0 * R0 - r * r;
  return q * d * d / (64.0 * s.bending_rigidity());
}

double uniform_load_max_deflection(const Sheet& s, double R0, double q) {
  return q * std::pow(R0, 4) / (64.0 * s.bending_rigidity());
}

double uniform_load_linear_limit(const Sheet& s, double R0) {
  return 64.0 * s.bending_rigidity() * (0.5 * s.thickness) / std::pow(R0, 4);
}

double plate_load_star(const Sheet& s, double R0, double q) {
  return q / s.youngs_modulus * std::pow(R0 / s.thickness, 4);
}

double plate_pressure_from_star(const Sheet& s, double R0, double star) {
  return star * s.youngs_modulus * std::pow(s.thickness / R0, 4);
}

double large_deflection_load_star(double nu, double w) {
  check_nu(nu);
  return 64.0 / (12.0 * (1.0 - nu * nu)) * w * (1.0 + 0.5 * (1.0 + nu) * w * w);
}

double large_deflection_max_deflection(double nu, double star) {
  check_nu(nu);
  if (!(std::isfinite(star) && star >= 0)) throw std::domain_error("large deflection: P* must be finite and >= 0");
  if (star == 0) return 0.0;
  // w (1 + b w^2) = c is monotone in w >= 0, and both w <= c (bending alone) and
  // w <= (c/b)^(1/3) (stretching alone) hold: the root is bracketed by [0, the smaller].
  const double c = 12.0 * (1.0 - nu * nu) / 64.0 * star;
  const double b = 0.5 * (1.0 + nu);
  struct P { double b, c; } p{b, c};
  gsl_function f;
  f.function = [](double w, void* v) {
    const auto* q = static_cast<P*>(v);
    return w * (1.0 + q->b * w * w) - q->c;
  };
  f.params = &p;
  const double hi = std::min(c, std::cbrt(c / b)) * (1.0 + 1e-12) + 1e-300;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &f, 0.0, hi);
  double w = 0.5 * hi;
  for (int it = 0; it < 200; ++it) {
    gsl_root_fsolver_iterate(solver.get());
    w = gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), 0.0,
                               1e-13) == GSL_SUCCESS)
      break;
  }
  return w;
}

}  // namespace cmp::elasticity
