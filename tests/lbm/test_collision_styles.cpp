// Every registered collision style: conservation, the equilibrium as a fixed point, the
// relaxation rates it claims, and Poiseuille flow through the full solver.
#include "lbm/collision.hpp"
#include "lbm/collision_styles.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/flow_solver.hpp"
#include "lbm/layout.hpp"
#include "lbm/pore_lattice.hpp"
#include "lbm/steady_state.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace cmp::lbm;
using Catch::Matchers::WithinAbs;

namespace {

void moments(const double f[19], double& rho, double j[3]) {
  rho = 0;
  j[0] = j[1] = j[2] = 0;
  for (int q = 0; q < kQ; ++q) {
    rho += f[q];
    j[0] += kCx[q] * f[q];
    j[1] += kCy[q] * f[q];
    j[2] += kCz[q] * f[q];
  }
}

void equilibrium(double rho, const double u[3], double f[19]) {
  for (int q = 0; q < kQ; ++q) {
    const double cu = kCx[q] * u[0] + kCy[q] * u[1] + kCz[q] * u[2];
    const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    f[q] = weight(q) * (rho + 3 * cu + 4.5 * cu * cu - 1.5 * uu);
  }
}

}  // namespace

TEST_CASE("D3Q19: weights sum to 1, lattice isotropy, opposite directions") {
  double w = 0, cxx = 0, cxy = 0;
  for (int q = 0; q < kQ; ++q) {
    w += weight(q);
    cxx += weight(q) * kCx[q] * kCx[q];
    cxy += weight(q) * kCx[q] * kCy[q];
    CHECK(kCx[opposite(q)] == -kCx[q]);
    CHECK(kCy[opposite(q)] == -kCy[q]);
    CHECK(kCz[opposite(q)] == -kCz[q]);
  }
  CHECK_THAT(w, WithinAbs(1, 1e-15));
  CHECK_THAT(cxx, WithinAbs(kCs2, 1e-15));
  CHECK_THAT(cxy, WithinAbs(0, 1e-15));
}

TEST_CASE("collision styles: registry names are unique and unknown names are refused") {
  REQUIRE(collision_styles().size() >= 3);
  CHECK(std::string(collision_styles()[0].name) == "mrt");
  for (const auto& s : collision_styles()) CHECK(std::string(collision_style(s.name).name) == s.name);
  CHECK_THROWS_AS(collision_style("lbgk"), cmp::UsageError);
  CHECK_THROWS_AS(collision_style("mrt").make({0.5, 3.0 / 16}), cmp::UsageError);
  CHECK_THROWS_AS(collision_style("trt").make({1.0, 0.0}), cmp::UsageError);
}

TEST_CASE("collision styles: every style conserves mass and momentum, keeps the equilibrium, adds the force") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  for (const auto& style : collision_styles()) {
    for (double tau : {0.6, 1.0, 1.7}) {
      INFO(style.name << " tau=" << tau);
      const auto op = style.make({tau, 3.0 / 16});
      CHECK(std::string(op->name()) == style.name);
      // Equilibrium is a fixed point.
      const double u[3] = {0.02, -0.01, 0.005};
      double feq[19], f[19];
      equilibrium(1.003, u, feq);
      std::copy(feq, feq + 19, f);
      op->collide(f, nullptr);
      for (int q = 0; q < kQ; ++q) CHECK_THAT(f[q], WithinAbs(feq[q], 1e-15));
      // Conservation for a perturbed state.
      for (int q = 0; q < kQ; ++q) f[q] = feq[q] + noise(rng) * weight(q);
      double rho0, j0[3], rho1, j1[3];
      moments(f, rho0, j0);
      op->collide(f, nullptr);
      moments(f, rho1, j1);
      CHECK_THAT(rho1, WithinAbs(rho0, 1e-14));
      for (int d = 0; d < 3; ++d) CHECK_THAT(j1[d], WithinAbs(j0[d], 1e-14));
      // A body force adds exactly g to the momentum (Guo forcing).
      const double g[3] = {1e-4, -2e-4, 3e-5};
      moments(f, rho0, j0);
      op->collide(f, g);
      moments(f, rho1, j1);
      CHECK_THAT(rho1, WithinAbs(rho0, 1e-14));
      for (int d = 0; d < 3; ++d) CHECK_THAT(j1[d], WithinAbs(j0[d] + g[d], 1e-14));
      // Non-equilibrium decays: the shear stress moment relaxes at exactly 1/tau.
      double s[19];
      for (int q = 0; q < kQ; ++q) s[q] = kCx[q] * kCy[q];
      op->relax(s);
      for (int q = 0; q < kQ; ++q) CHECK_THAT(s[q], WithinAbs(kCx[q] * kCy[q] / tau, 1e-14));
    }
  }
}

TEST_CASE("mrt, mrt-dh: every moment of the d'Humieres basis relaxes at its own rate") {
  // The basis written out from its definition (d'Humieres et al. 2002), independently of the
  // class sums the relaxation uses; R M_k must be s_k M_k for every non-conserved moment.
  const double tau = 0.8, s_nu = 1 / tau;
  struct Moment {
    const char* name;
    double (*row)(int x, int y, int z);
    int kind;  // 0 stress (s_nu), 1 e, 2 eps, 3 pi, 4 q (s_q), 5 m (s_m)
  };
  const Moment basis[] = {
      {"e", [](int x, int y, int z) { return 19.0 * (x * x + y * y + z * z) - 30; }, 1},
      {"eps", [](int x, int y, int z) { const double s = x * x + y * y + z * z; return (21 * s * s - 53 * s + 24) / 2; }, 2},
      {"q_x", [](int x, int y, int z) { return (5.0 * (x * x + y * y + z * z) - 9) * x; }, 4},
      {"q_y", [](int x, int y, int z) { return (5.0 * (x * x + y * y + z * z) - 9) * y; }, 4},
      {"q_z", [](int x, int y, int z) { return (5.0 * (x * x + y * y + z * z) - 9) * z; }, 4},
      {"3p_xx", [](int x, int y, int z) { return 3.0 * x * x - (x * x + y * y + z * z); }, 0},
      {"3pi_xx", [](int x, int y, int z) { const double s = x * x + y * y + z * z; return (3 * s - 5) * (3.0 * x * x - s); }, 3},
      {"p_ww", [](int, int y, int z) { return 1.0 * y * y - z * z; }, 0},
      {"pi_ww", [](int x, int y, int z) { return (3.0 * (x * x + y * y + z * z) - 5) * (y * y - z * z); }, 3},
      {"p_xy", [](int x, int y, int) { return 1.0 * x * y; }, 0},
      {"p_yz", [](int, int y, int z) { return 1.0 * y * z; }, 0},
      {"p_xz", [](int x, int, int z) { return 1.0 * x * z; }, 0},
      {"m_x", [](int x, int y, int z) { return (1.0 * y * y - z * z) * x; }, 5},
      {"m_y", [](int x, int y, int z) { return (1.0 * z * z - x * x) * y; }, 5},
      {"m_z", [](int x, int y, int z) { return (1.0 * x * x - y * y) * z; }, 5},
  };
  const double s_q = odd_rate({tau, 3.0 / 16});
  struct Style {
    const char* name;
    double s_q, s_m;
  };
  // mrt's even ghosts: tau_k - 1/2 in d'Humieres's ratio to tau - 1/2 at tau = 1 (so the steady
  // flow does not move with tau); mrt-dh's as printed.
  const auto scaled = [&](double printed) { return 1 / (0.5 + (1 / printed - 0.5) / 0.5 * (tau - 0.5)); };
  for (const Style& st : {Style{"mrt", s_q, s_q}, Style{"mrt-dh", 1.2, 1.98}}) {
    const bool dh = std::string(st.name) == "mrt-dh";
    const double rate[] = {s_nu, dh ? 1.19 : scaled(1.19), dh ? 1.4 : scaled(1.4), dh ? 1.4 : scaled(1.4), st.s_q, st.s_m};
    const auto op = collision_style(st.name).make({tau, 3.0 / 16});
    for (const Moment& m : basis) {
      INFO(st.name << " " << m.name);
      double g[19], expected[19];
      for (int q = 0; q < kQ; ++q) {
        g[q] = m.row(kCx[q], kCy[q], kCz[q]);
        expected[q] = rate[m.kind] * g[q];
      }
      op->relax(g);
      for (int q = 0; q < kQ; ++q) CHECK_THAT(g[q], WithinAbs(expected[q], 1e-12));
    }
  }
}

TEST_CASE("collision styles: the fused sweep is the one-node collision plus AA streaming, bit for bit") {
  // A periodic 4 x 4 x 2 box (4 blocks) with some links bounced back in pairs, random
  // populations; the sweep (on an AVX-512 processor its vector path) against collide() node by
  // node and the streaming written out, for every style, both AA parities, with and without force.
  const int nx = 4, ny = 4, nz = 2, n = nx * ny * nz;
  auto node = [&](int x, int y, int z) { return ((z + nz) % nz * ny + (y + ny) % ny) * nx + (x + nx) % nx; };
  std::vector<std::uint32_t> links(static_cast<std::size_t>(18 * (n + 4 * kBatch)), 0);  // padding for prefetches
  std::mt19937_64 rng(11);
  for (int i = 0; i < n; ++i)
    for (int q = 1; q <= kPairs; ++q) {
      const int j = node(i % nx + kCx[q], i / nx % ny + kCy[q], i / nx / ny + kCz[q]);
      const bool wall = rng() % 5 == 0;  // the link i -> j and its reverse j -> i both bounce back
      links[link_index(q, i)] = static_cast<std::uint32_t>(wall ? pop_slot(opposite(q), i) : pop_slot(q, j));
      links[link_index(opposite(q), j)] = static_cast<std::uint32_t>(wall ? pop_slot(q, j) : pop_slot(opposite(q), i));
    }
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  std::vector<double> start(static_cast<std::size_t>(kQ * n));
  for (int i = 0; i < n; ++i)
    for (int q = 0; q < kQ; ++q) start[pop_slot(q, i)] = weight(q) * (1 + noise(rng)) + 0.1 * weight(q) * kCx[q] * noise(rng);
  const double g[3] = {1e-4, -2e-4, 3e-5};
  // The lines of 8 consecutive slots (the z neighbours' lines, unless bounced back), which the
  // vector path may move with plain loads and stores: the same bits.
  std::vector<std::uint32_t> consecutive(static_cast<std::size_t>(n / kBatch));
  for (int b = 0; b < n / kBatch; ++b) consecutive[static_cast<std::size_t>(b)] = consecutive_lines(links.data(), b * kBatch);
  REQUIRE(std::any_of(consecutive.begin(), consecutive.end(), [](std::uint32_t bits) { return bits != 0; }));
  for (const auto& style : collision_styles()) {
    const auto op = style.make({0.8, 3.0 / 16});
    for (bool odd : {false, true})
      for (const double* force : {static_cast<const double*>(nullptr), g}) {
        INFO(style.name << (odd ? " odd" : " even") << (force ? " force" : ""));
        std::vector<double> swept = start, expected = start;
        op->sweep(SweepRange<double>{swept.data(), links.data(), 0, n, odd, force});
        for (int i = 0; i < n; ++i) {
          double f[kQ];
          for (int q = 0; q < kQ; ++q)
            f[q] = start[q == 0 || !odd ? pop_slot(q, i) : links[link_index(opposite(q), i)]];
          op->collide(f, force);
          for (int q = 0; q < kQ; ++q)
            expected[q == 0 ? pop_slot(0, i) : odd ? links[link_index(q, i)] : pop_slot(opposite(q), i)] = f[q];
        }
        CHECK(std::memcmp(swept.data(), expected.data(), swept.size() * sizeof(double)) == 0);
        std::vector<double> moved = start;
        op->sweep(SweepRange<double>{moved.data(), links.data(), 0, n, odd, force, consecutive.data()});
        CHECK(std::memcmp(moved.data(), expected.data(), moved.size() * sizeof(double)) == 0);
      }
  }
}

TEST_CASE("collision styles: every style gives plane Poiseuille flow within 3 % of h^2/12 (h = 8, tau = 1)") {
  const PoreLattice p = channel(2, 8, 0, 1);
  const double exact = 8.0 * 8.0 / 12 * 8.0 / 10.0;  // superficial: 8 fluid of 10 nodes across
  for (const auto& style : collision_styles()) {
    FlowSettings s;
    s.collision = style.name;
    s.driving = Driving::kBodyForce;
    const SteadyStateResult r = solve_steady(p, s, {1e-9, 50, 4, 100000});
    INFO(style.name << " kappa/exact " << r.final.kappa_lu / exact);
    REQUIRE(r.converged);
    CHECK(std::abs(r.final.kappa_lu / exact - 1) < 0.03);
  }
}
