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
// ghosts and, in mrt-dh, the three m moments, on the 10 even or 9 odd pair values that the
// sweep kernel hands over (lbm/sweep_kernel.hpp).
#include "lbm/collision_styles.hpp"
#include "lbm/sweep_kernel.hpp"

#include <initializer_list>

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

// Each even ghost row takes one value on the rest direction, on the three axes and on the six
// face diagonals, or one per axis and per coordinate plane: the moments below are sums over
// those classes (the general sums over 10 pairs for 4 moments, and the corrections back,
// took three times the operations).
constexpr bool same(std::initializer_list<double> values) {
  for (double v : values)
    if (v != *values.begin()) return false;
  return true;
}
constexpr auto& kE = kRows.even;
static_assert(same({kE[0][1], kE[0][2], kE[0][3]}) && same({kE[0][4], kE[0][5], kE[0][6], kE[0][7], kE[0][8], kE[0][9]}));
static_assert(same({kE[1][1], kE[1][2], kE[1][3]}) && same({kE[1][4], kE[1][5], kE[1][6], kE[1][7], kE[1][8], kE[1][9]}));
static_assert(kE[2][0] == 0 && kE[2][2] == kE[2][3] && same({kE[2][4], kE[2][5], kE[2][6], kE[2][7]}) && kE[2][8] == kE[2][9]);
static_assert(same({kE[3][0], kE[3][1], kE[3][8], kE[3][9], 0}) && kE[3][2] == -kE[3][3] &&
              same({kE[3][4], kE[3][5], -kE[3][6], -kE[3][7]}));
// Pairs 1..3 are the axes x, y, z; 4, 5 the xy diagonals, 6, 7 the xz ones, 8, 9 the yz ones.
static_assert(kCx[1] == 1 && kCy[2] == 1 && kCz[3] == 1 && kCz[4] == 0 && kCz[5] == 0 && kCy[6] == 0 && kCy[7] == 0 && kCx[8] == 0 && kCx[9] == 0);

// kOddGhosts: the m moments relax at their own rate (mrt-dh); without, s_m = s_q and the odd
// half is TRT's.
template <bool kOddGhosts>
struct MrtRelax {
  double s_nu, s_q;
  double even_coef[4];  // 2 (s_k - s_nu) / |M_k|^2: the 2 counts both members of a pair in M_k.g
  double odd_coef[3];   // 2 (s_m - s_q) / |M_k|^2

  template <class V>
  [[gnu::always_inline]] void operator()(V (&ev)[kPairs + 1], V (&od)[kPairs + 1]) const {
    constexpr auto& R = kE;
    // The ghost moments (M_k.g / 2, pairs counted once), times their coefficients.
    const V pxy = ev[4] + ev[5], pxz = ev[6] + ev[7], pyz = ev[8] + ev[9], ayz = ev[2] + ev[3];
    const V axes = ev[1] + ayz, diagonals = pxy + pxz + pyz;
    const V me = even_coef[0] * (0.5 * R[0][0] * ev[0] + R[0][1] * axes + R[0][4] * diagonals);
    const V meps = even_coef[1] * (0.5 * R[1][0] * ev[0] + R[1][1] * axes + R[1][4] * diagonals);
    const V mxx = even_coef[2] * (R[2][1] * ev[1] + R[2][2] * ayz + R[2][4] * (pxy + pxz) + R[2][8] * pyz);
    const V mww = even_coef[3] * (R[3][3] * (ev[3] - ev[2]) + R[3][4] * (pxy - pxz));
    // s_nu g+ plus sum_k M_k m_k, class by class.
    const V on_axes = R[0][1] * me + R[1][1] * meps, on_diagonals = R[0][4] * me + R[1][4] * meps;
    const V ayz_fix = on_axes + R[2][2] * mxx, ww_axis = R[3][3] * mww;
    const V dxy_fix = on_diagonals + R[2][4] * mxx, ww_diagonal = R[3][4] * mww;
    const V dyz_fix = on_diagonals + R[2][8] * mxx;
    ev[0] = s_nu * ev[0] + (R[0][0] * me + R[1][0] * meps);
    ev[1] = s_nu * ev[1] + (on_axes + R[2][1] * mxx);
    ev[2] = s_nu * ev[2] + (ayz_fix - ww_axis);
    ev[3] = s_nu * ev[3] + (ayz_fix + ww_axis);
    ev[4] = s_nu * ev[4] + (dxy_fix + ww_diagonal);
    ev[5] = s_nu * ev[5] + (dxy_fix + ww_diagonal);
    ev[6] = s_nu * ev[6] + (dxy_fix - ww_diagonal);
    ev[7] = s_nu * ev[7] + (dxy_fix - ww_diagonal);
    ev[8] = s_nu * ev[8] + dyz_fix;
    ev[9] = s_nu * ev[9] + dyz_fix;
    if constexpr (kOddGhosts) {
      V m[3];
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k) {
        m[k] = V{};
#pragma GCC unroll 9
        for (int p = 1; p <= kPairs; ++p)
          if (kRows.odd[k][p] != 0) m[k] += kRows.odd[k][p] * od[p];
        m[k] *= odd_coef[k];
      }
#pragma GCC unroll 9
      for (int p = 1; p <= kPairs; ++p) {
        od[p] *= s_q;
#pragma GCC unroll 3
        for (int k = 0; k < 3; ++k)
          if (kRows.odd[k][p] != 0) od[p] += kRows.odd[k][p] * m[k];
      }
    } else {
#pragma GCC unroll 9
      for (int p = 1; p <= kPairs; ++p) od[p] *= s_q;
    }
  }
};

template <class Real, bool kOddGhosts>
[[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void sweep_mrt(const SweepRange<Real>& r, const MrtRelax<kOddGhosts>& relax) {
  kernel::sweep(r, relax);
}

// d'Humieres et al. (2002) rates of the even ghost moments e, eps, pi_xx/pi_ww.
constexpr double kSe = 1.19, kSeps = 1.4, kSpi = 1.4;

// `mrt`: the even ghosts' rates at tau, each relaxation time tau_k - 1/2 in the ratio to
// tau - 1/2 that d'Humieres's rates have at tau = 1. With the odd rates from Lambda, every
// product (tau_even - 1/2)(tau_odd - 1/2) is then the same for every tau, and so is the steady
// flow (Ginzburg's parametrisation): held at the printed rates instead, kappa of a jammed
// cluster fell by 30 % from tau = 1 to 0.52.
double scaled_even_rate(double printed, double tau) {
  if (tau == 1.0) return printed;
  return 1.0 / (0.5 + (1.0 / printed - 0.5) / 0.5 * (tau - 0.5));
}

template <bool kOddGhosts>
std::unique_ptr<CollisionOperator> make(const char* name, const CollisionParameters& p, double s_q, double s_m,
                                        bool scaled_ghosts) {
  check_collision_parameters(p);
  MrtRelax<kOddGhosts> r{};
  r.s_nu = 1.0 / p.tau;
  r.s_q = s_q;
  const auto even = [&](double printed) { return scaled_ghosts ? scaled_even_rate(printed, p.tau) : printed; };
  const double even_rates[4] = {even(kSe), even(kSeps), even(kSpi), even(kSpi)};
  for (int k = 0; k < 4; ++k) r.even_coef[k] = 2 * (even_rates[k] - r.s_nu) / kRows.even_norm[k];
  for (int k = 0; k < 3; ++k) r.odd_coef[k] = 2 * (s_m - s_q) / kRows.odd_norm[k];
  return std::make_unique<kernel::OperatorFrom<MrtRelax<kOddGhosts>>>(name, r, &sweep_mrt<double, kOddGhosts>,
                                                                      &sweep_mrt<float, kOddGhosts>);
}

}  // namespace

std::unique_ptr<CollisionOperator> make_mrt(const CollisionParameters& p) {
  check_collision_parameters(p);
  return make<false>("mrt", p, odd_rate(p), odd_rate(p), true);
}

std::unique_ptr<CollisionOperator> make_mrt_dh(const CollisionParameters& p) { return make<true>("mrt-dh", p, 1.2, 1.98, false); }

}  // namespace cmp::lbm
