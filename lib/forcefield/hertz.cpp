#include "forcefield/hertz.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace cmp {

void HertzMaterial::validate() const {
  if (!(youngs_modulus > 0) || !std::isfinite(youngs_modulus)) throw UsageError("Young's modulus must be positive");
  if (!(poisson_ratio > -1 && poisson_ratio < 1)) throw UsageError("Poisson's ratio must lie in (-1, 1)");
}

}  // namespace cmp
