// MRT (multiple relaxation times) in the orthogonal moment basis of d'Humieres, Ginzburg,
// Krafczyk, Lallemand & Luo (2002), Phil. Trans. R. Soc. A 360, 437, for D3Q19:
//   rho, e = 19c^2 - 30, eps = (21c^4 - 53c^2 + 24)/2, j, q = (5c^2 - 9) c,
//   3p_xx = 3c_x^2 - c^2, 3pi_xx = (3c^2 - 5)(3c_x^2 - c^2), p_ww = c_y^2 - c_z^2,
//   pi_ww = (3c^2 - 5)(c_y^2 - c_z^2), p_xy, p_yz, p_xz, m_x = (c_y^2 - c_z^2) c_x (and cyclic).
// Rates: stress moments (3p_xx, p_ww, p_xy, p_yz, p_xz) s_nu = 1/tau; their paper's
// s_e = 1.19, s_eps = 1.4, s_pi = 1.4 for the even ghosts; odd moments q and m:
//   `mrt`    s_q = s_m = s_- from the magic parameter (Lambda = 3/16 by default), as in TRT,
//            so the bounce-back wall and the permeability do not move with tau (the choice
//            of Pan, Luo & Miller 2006 for porous media; at tau = 1, s_- = 8/7 ~ d'Humieres's 1.2);
//   `mrt-dh` s_q = 1.2, s_m = 1.98 as printed: Lambda = (tau - 1/2)/3 varies with tau.
//
// Implementation: the basis is orthogonal, so the collision R g = sum_k s_k M_k (M_k.g)/|M_k|^2
// is s_nu g+ (even part) + s_q g- (odd part) plus rank-one corrections for the four even
// ghosts and the three m moments, each on the 10 even or 9 odd pair values.
#include "lbm/collision_styles.hpp"
#include "lbm/sweep_kernel.hpp"

namespace cmp::lbm {

namespace {

constexpr double c2(int q) { return kCx[q] * kCx[q] + kCy[q] * kCy[q] + kCz[q] * kCz[q]; }

// Moment rows on the directions 0..9 (the even and odd rows are fixed by them).
struct Rows {
  double even[4][10];  // e, eps, 3pi_xx, pi_ww
  double odd[3][10];   // m_x, m_y, m_z (index 0 unused)
  double even_norm[4], odd_norm[3];
};

constexpr Rows make_rows() {
  Rows r{};
  for (int q = 0; q <= kPairs; ++q) {
    const double s = c2(q), x2 = kCx[q] * kCx[q], y2 = kCy[q] * kCy[q], z2 = kCz[q] * kCz[q];
    r.even[0][q] = 19 * s - 30;
    r.even[1][q] = (21 * s * s - 53 * s + 24) / 2;
    r.even[2][q] = (3 * s - 5) * (3 * x2 - s);
    r.even[3][q] = (3 * s - 5) * (y2 - z2);
    r.odd[0][q] = (y2 - z2) * kCx[q];
    r.odd[1][q] = (z2 - x2) * kCy[q];
    r.odd[2][q] = (x2 - y2) * kCz[q];
  }
  for (int k = 0; k < 4; ++k) {  // |M_k|^2 over all 19 directions: rest once, pairs twice
    double n = r.even[k][0] * r.even[k][0];
    for (int p = 1; p <= kPairs; ++p) n += 2 * r.even[k][p] * r.even[k][p];
    r.even_norm[k] = n;
  }
  for (int k = 0; k < 3; ++k) {
    double n = 0;
    for (int p = 1; p <= kPairs; ++p) n += 2 * r.odd[k][p] * r.odd[k][p];
    r.odd_norm[k] = n;
  }
  return r;
}

constexpr Rows kRows = make_rows();

struct MrtRelax {
  double s_nu, s_q;
  double even_coef[4];  // 2 (s_k - s_nu) / |M_k|^2: the 2 counts both members of a pair in M_k.g
  double odd_coef[3];   // 2 (s_m - s_q) / |M_k|^2

  template <class V>
  [[gnu::always_inline]] void operator()(V (&g)[kQ]) const {
    V ev[kPairs + 1], od[kPairs + 1];
    ev[0] = g[0];
    od[0] = V{};
#pragma GCC unroll 9
    for (int p = 1; p <= kPairs; ++p) {
      ev[p] = 0.5 * (g[p] + g[p + kPairs]);
      od[p] = 0.5 * (g[p] - g[p + kPairs]);
    }
    V oute[kPairs + 1], outo[kPairs + 1];
#pragma GCC unroll 10
    for (int q = 0; q <= kPairs; ++q) {
      oute[q] = s_nu * ev[q];
      outo[q] = s_q * od[q];
    }
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
      V m = 0.5 * kRows.even[k][0] * ev[0];
#pragma GCC unroll 9
      for (int p = 1; p <= kPairs; ++p)
        if (kRows.even[k][p] != 0) m += kRows.even[k][p] * ev[p];
      m *= even_coef[k];
#pragma GCC unroll 10
      for (int q = 0; q <= kPairs; ++q)
        if (kRows.even[k][q] != 0) oute[q] += kRows.even[k][q] * m;
    }
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
      V m{};
#pragma GCC unroll 9
      for (int p = 1; p <= kPairs; ++p)
        if (kRows.odd[k][p] != 0) m += kRows.odd[k][p] * od[p];
      m *= odd_coef[k];
#pragma GCC unroll 9
      for (int p = 1; p <= kPairs; ++p)
        if (kRows.odd[k][p] != 0) outo[p] += kRows.odd[k][p] * m;
    }
    g[0] = oute[0];
#pragma GCC unroll 9
    for (int p = 1; p <= kPairs; ++p) {
      g[p] = oute[p] + outo[p];
      g[p + kPairs] = oute[p] - outo[p];
    }
  }
};

template <class Real>
[[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void sweep_mrt(const SweepRange<Real>& r, const MrtRelax& relax) {
  kernel::sweep(r, relax);
}

// d'Humieres et al. (2002) rates of the even ghost moments e, eps, pi_xx/pi_ww.
constexpr double kSe = 1.19, kSeps = 1.4, kSpi = 1.4;

std::unique_ptr<CollisionOperator> make(const char* name, const CollisionParameters& p, double s_q, double s_m) {
  check_collision_parameters(p);
  MrtRelax r{};
  r.s_nu = 1.0 / p.tau;
  r.s_q = s_q;
  const double even_rates[4] = {kSe, kSeps, kSpi, kSpi};
  for (int k = 0; k < 4; ++k) r.even_coef[k] = 2 * (even_rates[k] - r.s_nu) / kRows.even_norm[k];
  for (int k = 0; k < 3; ++k) r.odd_coef[k] = 2 * (s_m - s_q) / kRows.odd_norm[k];
  return std::make_unique<kernel::OperatorFrom<MrtRelax>>(name, r, &sweep_mrt<double>, &sweep_mrt<float>);
}

}  // namespace

std::unique_ptr<CollisionOperator> make_mrt(const CollisionParameters& p) {
  check_collision_parameters(p);
  return make("mrt", p, odd_rate(p), odd_rate(p));
}

std::unique_ptr<CollisionOperator> make_mrt_dh(const CollisionParameters& p) { return make("mrt-dh", p, 1.2, 1.98); }

}  // namespace cmp::lbm
