#include "elasticity/buckling.hpp"

#include <cmath>
#include <stdexcept>

namespace cmp::elasticity {

namespace {
void positive(double x, const char* what) {
  if (!(std::isfinite(x) && x > 0)) throw std::domain_error(std::string(what) + " must be positive and finite");
}
double factor(HingeCalibration c) {
  switch (c) {
    case HingeCalibration::Cylinder: return std::sqrt(3.0) / 2.0;
    case HingeCalibration::Sphere: return 1.0 / (2.0 * std::sqrt(3.0));
  }
  throw std::domain_error("unknown hinge calibration");
}
}  // namespace

double buckling_pressure(double Y, double kappa, double R0) {
  positive(Y, "Y");
  positive(kappa, "kappa");
  positive(R0, "R0");
  return 4.0 * std::sqrt(kappa * Y) / (R0 * R0);
}

double buckling_pressure(const Sheet& s, double R0) {
  return buckling_pressure(s.stretching_modulus(), s.bending_rigidity(), R0);
}

double foppl_von_karman(double Y, double kappa, double R0) {
  positive(Y, "Y");
  positive(kappa, "kappa");
  positive(R0, "R0");
  return Y * R0 * R0 / kappa;
}

double foppl_von_karman(const Sheet& s, double R0) {
  return foppl_von_karman(s.stretching_modulus(), s.bending_rigidity(), R0);
}

double radius_over_thickness(double gamma, double nu) {
  positive(gamma, "gamma");
  return std::sqrt(gamma / (12.0 * (1.0 - nu * nu)));
}

double spring_stretching_modulus(double k) { return 2.0 * k / std::sqrt(3.0); }
double spring_constant(double Y) { return std::sqrt(3.0) * Y / 2.0; }

double hinge_bending_rigidity(double kt, HingeCalibration c) {
  positive(kt, "kappa~");
  return factor(c) * kt;
}

double hinge_gaussian_modulus(double kt) {
  positive(kt, "kappa~");
  return -2.0 / std::sqrt(3.0) * kt;
}

double hinge_constant(double kappa, HingeCalibration c) {
  positive(kappa, "kappa");
  return kappa / factor(c);
}

}  // namespace cmp::elasticity
