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

void validate(const ContactParameters& p, const char* style) {
  const std::string s = style;
  if (!(std::isfinite(p.vertex_radius) && p.vertex_radius > 0))
    throw UsageError(s + ": vertex radius R_v = " + num(p.vertex_radius) + " must be positive and finite");
  if (!(std::isfinite(p.contact_distance) && p.contact_distance > 0))
    throw UsageError(s + ": contact distance delta = " + num(p.contact_distance) + " must be positive and finite");
  if (!(std::isfinite(p.youngs_modulus) && p.youngs_modulus > 0))
    throw UsageError(s + ": Young's modulus E = " + num(p.youngs_modulus) + " must be positive and finite");
  if (!(p.wall_modulus > 0)) throw UsageError(s + ": wall modulus E_w = " + num(p.wall_modulus) + " must be positive");
  if (!(p.poisson_ratio > -1.0 && p.poisson_ratio <= 0.5))
    throw UsageError(s + ": Poisson ratio nu = " + num(p.poisson_ratio) + " must be in (-1, 0.5]");
  if (!(p.wall_poisson_ratio > -1.0 && p.wall_poisson_ratio <= 0.5))
    throw UsageError(s + ": wall Poisson ratio nu_w = " + num(p.wall_poisson_ratio) + " must be in (-1, 0.5]");
  for (const Plane& w : p.walls)
    if (!w.point.allFinite() || !w.normal.allFinite() || std::abs(w.normal.norm() - 1.0) > 1e-12)
      throw UsageError(s + ": a wall needs a finite point and a unit normal");
}

}  // namespace cmp::shell
