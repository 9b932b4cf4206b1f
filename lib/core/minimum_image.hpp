#pragma once
// Periodic boundaries along one axis, the one place they are written, so every tool wraps
// alike: the minimum image of a separation (Hertz forces, neighbour lists, voxel marking,
// unwrapping) and a coordinate wrapped into the box (files, Voronoi cells, cell grids).
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

// x wrapped into [0, period): x - period floor(x / period), and 0 where round-off puts it at
// period or a hair below 0 (x just below a multiple of the period).
inline double wrap_into_period(double x, double period) {
  const double w = x - period * std::floor(x / period);
  return w >= period || w < 0 ? 0.0 : w;
}

}  // namespace cmp
