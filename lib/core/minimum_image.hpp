#pragma once
// The minimum image of a separation along one periodic axis: the one place it is written, so
// every tool wraps distances alike (Hertz forces, neighbour lists, voxel marking, unwrapping).
#include <cmath>

namespace cmp {

// d reduced to its nearest periodic image along an axis of the given period: a value in
// [-period/2, period/2] (ties at exactly period/2 go either way). Works for any d, not only
// |d| < period. The hot loops keep 1/period and pass it (a multiplication instead of a
// division: a different rounding, so each caller keeps the form it has always used).
inline double minimum_image(double d, double period) { return d - period * std::nearbyint(d / period); }
inline double minimum_image(double d, double period, double inverse_period) {
  return d - period * std::nearbyint(d * inverse_period);
}

}  // namespace cmp
