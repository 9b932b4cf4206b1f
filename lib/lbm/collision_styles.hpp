#pragma once
// The constructors behind the registry table of lbm/collision.hpp (one per style file).
#include "lbm/collision.hpp"

namespace cmp::lbm {

std::unique_ptr<CollisionOperator> make_bgk(const CollisionParameters& p);  // bgk.cpp
std::unique_ptr<CollisionOperator> make_trt(const CollisionParameters& p);  // trt.cpp
// mrt.cpp: d'Humieres et al. (2002) rates for the even ghost moments; the odd (energy-flux
// and third-order) moments from the magic parameter (`mrt`) or at d'Humieres's 1.2 / 1.98
// (`mrt-dh`).
std::unique_ptr<CollisionOperator> make_mrt(const CollisionParameters& p);
std::unique_ptr<CollisionOperator> make_mrt_dh(const CollisionParameters& p);

// Rate of the odd moments that makes Lambda = (tau - 1/2)(1/s_- - 1/2) equal `magic`.
double odd_rate(const CollisionParameters& p);

}  // namespace cmp::lbm
