#include "shell/shell_parameters.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace cmp::shell {

namespace {
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
}  // namespace

void validate(const MaterialParameters& p, const char* style) {
  const std::string s = style;
  if (!(std::isfinite(p.youngs_modulus) && p.youngs_modulus > 0))
    throw UsageError(s + ": Young's modulus E = " + num(p.youngs_modulus) + " must be positive and finite");
  if (!(std::isfinite(p.thickness) && p.thickness > 0))
    throw UsageError(s + ": thickness t = " + num(p.thickness) + " must be positive and finite");
  if (!(p.poisson_ratio > -1.0 && p.poisson_ratio <= 0.5))
    throw UsageError(s + ": Poisson ratio nu = " + num(p.poisson_ratio) + " must be in (-1, 0.5]");
}

void validate(const PressureParameters& p, const char* style) {
  if (!std::isfinite(p.turgor))
    throw UsageError(std::string(style) + ": pressure Pi = " + num(p.turgor) + " must be finite");
}

}  // namespace cmp::shell
