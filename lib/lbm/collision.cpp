#include "lbm/collision.hpp"

#include "lbm/collision_styles.hpp"

#include "core/errors.hpp"
#include "core/registry.hpp"

#include <cmath>

namespace cmp::lbm {

namespace {

const CollisionStyle kStyles[] = {
    {"mrt", "MRT, d'Humieres et al. 2002 moments and ghost rates, odd rates from the magic parameter (tau-independent walls)",
     &make_mrt},
    {"mrt-dh", "MRT with all of d'Humieres et al. 2002's rates (s_q = 1.2, s_m = 1.98): walls move slightly with tau",
     &make_mrt_dh},
    {"trt", "two relaxation times, s+ = 1/tau, s- from the magic parameter (default 3/16)", &make_trt},
    {"bgk", "single relaxation time 1/tau (walls and permeability move with tau)", &make_bgk},
};

}  // namespace

std::span<const CollisionStyle> collision_styles() { return kStyles; }

const CollisionStyle& collision_style(const std::string& name) {
  return find_style(collision_styles(), name, "collision model");
}

void check_collision_parameters(const CollisionParameters& p) {
  if (!(p.tau > 0.5) || !std::isfinite(p.tau))
    throw UsageError("tau must be above 1/2 (nu = (tau - 1/2)/3 > 0), got " + std::to_string(p.tau));
  if (!(p.magic > 0) || !std::isfinite(p.magic))
    throw UsageError("the magic parameter must be positive, got " + std::to_string(p.magic));
}

}  // namespace cmp::lbm
