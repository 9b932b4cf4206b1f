#include "elasticity/von_karman_plate.hpp"

#include "core/errors.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace cmp::elasticity {

namespace {
// Units: R0 = 1, t = 1, E = 1, so q = P*, D = 1/(12 (1 - nu^2)), w in t.
struct Plate {
  double nu, D, q;
};

// y = (phi, M, N, G, w), G = (r^2 N)'/r = r N' + 2 N.
int rhs(double r, const double y[], double dy[], void* params) {
  const auto* p = static_cast<Plate*>(params);
  dy[0] = y[1] - y[0] / r;
  dy[1] = (p->q * r / 2 + y[2] * y[0]) / p->D;
  dy[2] = (y[3] - 2 * y[2]) / r;
  dy[3] = -0.5 * y[0] * y[0] / r;
  dy[4] = y[0];
  for (int i = 0; i < 5; ++i)
    if (!std::isfinite(dy[i])) return GSL_EBADFUNC;
  return GSL_SUCCESS;
}

constexpr double kStart = 1e-6;
constexpr int kSegments = 8;  // multiple shooting: each segment amplifies the edge layer's growing mode by at most e^(1/(8 l))
constexpr int kUnknowns = 2 + 4 * (kSegments - 1);

bool integrate(Plate& p, double r0, double r1, double* y) {
  gsl_odeiv2_system sys{rhs, nullptr, 5, &p};
  std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> d(
      gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, 1e-12, 1e-12), gsl_odeiv2_driver_free);
  gsl_odeiv2_driver_set_nmax(d.get(), 1000000);
  double r = r0;
  return gsl_odeiv2_driver_apply(d.get(), &r, r1, y) == GSL_SUCCESS;
}

double node(int k) { return static_cast<double>(k) / kSegments; }

// Unknowns u: (M0, N0) at the centre, then (phi, M, N, G) at each interior node. Fills the
// residuals (continuity at the interior nodes, then phi(1) and the immovable-edge condition)
// and the central deflection w(0) - w(1) (in t). False when an integration fails.
bool shoot(Plate& p, const double* u, double* f, double& w_centre) {
  double y[5];
  const double M0 = u[0], N0 = u[1];
  y[0] = 0.5 * M0 * kStart;  // the regular series at the centre
  y[1] = M0 + p.q * kStart * kStart / (4 * p.D);
  y[2] = N0;
  y[3] = 2 * N0;
  y[4] = 0;
  double drop = 0;
  for (int k = 0; k < kSegments; ++k) {
    if (k > 0) {
      const double* s = u + 2 + 4 * (k - 1);
      for (int i = 0; i < 4; ++i) f[4 * (k - 1) + i] = y[i] - s[i];
      for (int i = 0; i < 4; ++i) y[i] = s[i];
      y[4] = 0;
    }
    if (!integrate(p, k == 0 ? kStart : node(k), node(k + 1), y)) return false;
    drop += y[4];
  }
  f[4 * (kSegments - 1)] = y[0];
  f[4 * (kSegments - 1) + 1] = y[3] - (1 + p.nu) * y[2];
  w_centre = -drop;  // w(1) - w(0) = sum of the segments' increments
  return true;
}

int plate_residuals(const gsl_vector* x, void* params, gsl_vector* f) {
  auto* p = static_cast<Plate*>(params);
  double u[kUnknowns], r[kUnknowns], w;
  for (int i = 0; i < kUnknowns; ++i) u[i] = gsl_vector_get(x, static_cast<std::size_t>(i));
  if (!shoot(*p, u, r, w)) return GSL_EBADFUNC;
  for (int i = 0; i < kUnknowns; ++i) gsl_vector_set(f, static_cast<std::size_t>(i), r[i]);
  return GSL_SUCCESS;
}
}  // namespace

std::vector<double> von_karman_max_deflection(double nu, const std::vector<double>& stars) {
  if (!(nu > -1 && nu < 0.5)) throw std::domain_error("von Karman plate: nu must be in (-1, 0.5)");
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
  Plate p{nu, 1.0 / (12 * (1 - nu * nu)), 0.0};
  std::vector<double> out;
  // Start from the linear solution at a small load (phi = -q r (1 - r^2)/(16 D),
  // M = -q (1 - 2 r^2)/(8 D), no membrane force) and continue in steps of at most 10 %.
  double q = std::min(1e-3, stars.empty() ? 1e-3 : stars.front()), q_prev = 0;
  std::vector<double> u(kUnknowns, 0.0), u_prev(kUnknowns, 0.0);
  u[0] = -q / (8 * p.D);
  for (int k = 1; k < kSegments; ++k) {
    const double r = node(k);
    u[2 + 4 * (k - 1)] = -q * r * (1 - r * r) / (16 * p.D);
    u[2 + 4 * (k - 1) + 1] = -q * (1 - 2 * r * r) / (8 * p.D);
  }
  std::unique_ptr<gsl_multiroot_fsolver, decltype(&gsl_multiroot_fsolver_free)> solver(
      gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, kUnknowns), gsl_multiroot_fsolver_free);
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(kUnknowns), gsl_vector_free);
  double previous = 0, w_centre = 0;
  std::vector<double> f(kUnknowns);
  bool first = true;
  for (double target : stars) {
    if (!(std::isfinite(target) && target > previous)) throw std::domain_error("von Karman plate: P* must increase from 0");
    previous = target;
    while (true) {
      const double next = first ? q : std::min(target, q * 1.1);
      p.q = next;
      // Guess: the last two solutions extrapolated linearly in q.
      for (int i = 0; i < kUnknowns; ++i) {
        const double slope = q_prev > 0 ? (u[i] - u_prev[i]) / (q - q_prev) : u[i] / q;
        gsl_vector_set(x.get(), static_cast<std::size_t>(i), first ? u[i] : u[i] + slope * (next - q));
      }
      first = false;
      gsl_multiroot_function F{plate_residuals, kUnknowns, &p};
      int status = gsl_multiroot_fsolver_set(solver.get(), &F, x.get());
      for (int it = 0; status == GSL_SUCCESS; ++it) {
        if (it == 200) {
          status = GSL_EMAXITER;
          break;
        }
        status = gsl_multiroot_fsolver_iterate(solver.get());
        if (status == GSL_SUCCESS && gsl_multiroot_test_delta(solver->dx, solver->x, 1e-300, 1e-12) == GSL_SUCCESS) break;
      }
      // The hybrid solver may stop for lack of progress at the root itself: judge by the
      // residuals relative to the size of the unknowns they compare.
      std::vector<double> v(kUnknowns);
      for (int i = 0; i < kUnknowns; ++i) v[i] = gsl_vector_get(solver->x, static_cast<std::size_t>(i));
      double size = 0, mismatch = INFINITY;
      for (double vi : v) size = std::max(size, std::abs(vi));
      if (shoot(p, v.data(), f.data(), w_centre)) {
        mismatch = 0;
        for (double fi : f) mismatch = std::max(mismatch, std::abs(fi) / size);
      }
      if (!(mismatch < 1e-9)) {
        std::ostringstream msg;
        msg << "von Karman plate: no solution at P* = " << next << " (relative mismatch " << mismatch << ")";
        throw ComputationError(msg.str());
      }
      if (next > q) {  // (the first solve only refines the linear guess at the same load)
        u_prev = u;
        q_prev = q;
      }
      u = v;
      q = next;
      if (q >= target) break;
    }
    out.push_back(w_centre);
  }
  return out;
}

}  // namespace cmp::elasticity
