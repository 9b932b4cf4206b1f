#pragma once
// The D3Q19 velocity set: 19 lattice velocities c_q (the rest velocity, the 6 faces and the 12
// edges of the unit cube) and their weights w_q (1/3, 1/18, 1/36); lattice sound speed
// c_s^2 = 1/3. Directions are ordered so that q and q + 9 are opposite (q = 1..9), which makes
// the even/odd (symmetric/antisymmetric) split of TRT and MRT a loop over 9 pairs.
#include <array>

namespace cmp::lbm {

inline constexpr int kQ = 19;
inline constexpr int kPairs = 9;  // q = 1..9 and their opposites q + 9
inline constexpr double kCs2 = 1.0 / 3.0;

// c_q components, q = 0..18.
inline constexpr int kCx[kQ] = {0, 1, 0, 0, 1, 1, 1, 1, 0, 0, -1, 0, 0, -1, -1, -1, -1, 0, 0};
inline constexpr int kCy[kQ] = {0, 0, 1, 0, 1, -1, 0, 0, 1, 1, 0, -1, 0, -1, 1, 0, 0, -1, -1};
inline constexpr int kCz[kQ] = {0, 0, 0, 1, 0, 0, 1, -1, 1, -1, 0, 0, -1, 0, 0, -1, 1, -1, 1};

// Component `axis` (0, 1, 2) of c_q.
constexpr int velocity(int q, int axis) { return axis == 0 ? kCx[q] : axis == 1 ? kCy[q] : kCz[q]; }

// Weight w_q.
constexpr double weight(int q) {
  const int c2 = kCx[q] * kCx[q] + kCy[q] * kCy[q] + kCz[q] * kCz[q];
  return c2 == 0 ? 1.0 / 3.0 : c2 == 1 ? 1.0 / 18.0 : 1.0 / 36.0;
}

// The direction opposite to q.
constexpr int opposite(int q) { return q == 0 ? 0 : q <= kPairs ? q + kPairs : q - kPairs; }

}  // namespace cmp::lbm
