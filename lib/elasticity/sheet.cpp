#include "elasticity/sheet.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <string>

namespace cmp::elasticity {

void validate(const Sheet& s, const char* who) {
  const std::string w = who;
  if (!(std::isfinite(s.youngs_modulus) && s.youngs_modulus > 0))
    throw UsageError(w + ": Young's modulus E must be positive and finite, got " + std::to_string(s.youngs_modulus));
  if (!(std::isfinite(s.thickness) && s.thickness > 0))
    throw UsageError(w + ": thickness t must be positive and finite, got " + std::to_string(s.thickness));
  if (!(s.poisson_ratio > -1.0 && s.poisson_ratio <= 0.5))
    throw UsageError(w + ": Poisson ratio nu must be in (-1, 0.5], got " + std::to_string(s.poisson_ratio));
}

double poisson_ratio_from_strains(double eps_axial, double eps_transverse) {
  if (!std::isfinite(eps_axial) || !std::isfinite(eps_transverse) || eps_axial == 0.0)
    throw ComputationError("Poisson ratio: the axial strain must be finite and non-zero");
  return -eps_transverse / eps_axial;
}

}  // namespace cmp::elasticity
