#include "elasticity/membrane_contact.hpp"

#include "core/errors.hpp"
#include "elasticity/pressurised_sphere.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>

namespace cmp::elasticity {

namespace {

void gsl_errors_off() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

// Everything below is dimensionless: lengths in R0, tensions in Y = E t, pressures in Y/R0.
struct Material {
  double nu, k;  // k = 1/(2 (1 - nu^2))
  double T1(double l1, double l2) const { return k * (l1 / l2) * (l1 * l1 + nu * l2 * l2 - 1 - nu); }
  double T2(double l1, double l2) const { return k * (l2 / l1) * (l2 * l2 + nu * l1 * l1 - 1 - nu); }
  double f1(double l1, double l2) const { return k / l2 * (3 * l1 * l1 + nu * l2 * l2 - 1 - nu); }
  double f2(double l1, double l2) const { return k * l1 / (l2 * l2) * (nu * l2 * l2 - l1 * l1 + 1 + nu); }
  // The SVK energy per rest area (Eq. B.92's integrand, k/4 (...)).
  double W(double l1, double l2) const {
    const double a = l1 * l1 - 1, b = l2 * l2 - 1;
    return 0.25 * k * (a * a + b * b + 2 * nu * a * b);
  }
};

struct OdeParams {
  Material m;
  double p;  // pressure P R0/Y
};

// l1' for a meridian angle theta at rest angle psi (both regions).
double dl1(const Material& m, double psi, double l1, double l2, double theta, double& dl2) {
  const double s = std::sin(psi), c = std::cos(theta);
  dl2 = (l1 * c - l2 * std::cos(psi)) / s;
  const double dT1 = l1 * c * (m.T2(l1, l2) - m.T1(l1, l2)) / (l2 * s);
  return (dT1 - m.f2(l1, l2) * dl2) / m.f1(l1, l2);
}

// Contact region: y = (l1, l2, elastic energy), theta = 0.
int contact_rhs(double psi, const double y[], double dy[], void* params) {
  const auto* P = static_cast<OdeParams*>(params);
  dy[0] = dl1(P->m, psi, y[0], y[1], 0.0, dy[1]);
  dy[2] = 2 * M_PI * std::sin(psi) * P->m.W(y[0], y[1]);
  return std::isfinite(dy[0]) && std::isfinite(dy[1]) ? GSL_SUCCESS : GSL_EBADFUNC;
}

// Free region: y = (l1, l2, theta, eta, half volume, elastic energy).
int free_rhs(double psi, const double y[], double dy[], void* params) {
  const auto* P = static_cast<OdeParams*>(params);
  const double l1 = y[0], l2 = y[1], theta = y[2];
  if (!(l1 > 0 && l2 > 0)) return GSL_EBADFUNC;
  const double rho = l2 * std::sin(psi), T1 = P->m.T1(l1, l2), T2 = P->m.T2(l1, l2);
  if (!(T1 > 0)) return GSL_EBADFUNC;  // a slack meridian: no membrane solution
  dy[0] = dl1(P->m, psi, l1, l2, theta, dy[1]);
  dy[2] = l1 * (P->p - T2 * std::sin(theta) / rho) / T1;
  dy[3] = -l1 * std::sin(theta);
  dy[4] = M_PI * rho * rho * l1 * std::sin(theta);
  dy[5] = 2 * M_PI * std::sin(psi) * P->m.W(l1, l2);
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(dy[i])) return GSL_EBADFUNC;
  return GSL_SUCCESS;
}

struct Shot {
  bool ok = false;
  double psi_end = 0;                          // where theta reached pi/2 (<= pi/2)
  double theta = 0, eta = 0, half_volume = 0;  // there
  double l1 = 0, l2 = 0;                       // there
  double l1c = 0, l2c = 0;                     // at the contact edge
  double energy = 0;                           // elastic energy of the upper half
  // The shooting condition: 0 when the meridian becomes vertical exactly at the equator;
  // > 0 when it turns vertical early (psi_end < pi/2: the meridian curls, the pole stretch
  // is too low), < 0 when it is still inclined at the equator (theta - pi/2).
  double condition() const { return psi_end < M_PI / 2 ? M_PI / 2 - psi_end : theta - M_PI / 2; }
};


// The start of the contact region: the pole is singular (sin psi = 0), so the regular
// solution l1 = l2 = l0 + O(psi^2) is started a little off it.
double pole_start(double gamma) { return std::min(1e-7, 1e-4 * gamma); }

// Integrates y' = f over [t, t1] with the RK8(9) Prince-Dormand pair, stopping early when
// y[stop] reaches `limit` (linear interpolation inside the last step); calls visit(t, y) at each
// point of `at` in (t, t1]. Returns false when the integration fails.
template <class Visit>
bool integrate(int (*f)(double, const double*, double*, void*), std::size_t n, void* params, double& t, double t1,
               double* y, double tol, int stop, double limit, const std::vector<double>& at, std::size_t& next,
               Visit visit) {
  gsl_odeiv2_system sys{f, nullptr, n, params};
  std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)> step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, n),
                                                                         gsl_odeiv2_step_free);
  std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)> control(gsl_odeiv2_control_y_new(tol, tol),
                                                                                   gsl_odeiv2_control_free);
  std::unique_ptr<gsl_odeiv2_evolve, decltype(&gsl_odeiv2_evolve_free)> evolve(gsl_odeiv2_evolve_alloc(n),
                                                                               gsl_odeiv2_evolve_free);
  double h = std::min(1e-3, 0.5 * (t1 - t));
  std::vector<double> prev(n);
  for (int steps = 0; t < t1; ++steps) {
    if (steps > 100000) return false;
    const double t0 = t;
    std::copy(y, y + n, prev.begin());
    // Do not step past the next output point.
    const double target = next < at.size() && at[next] < t1 ? at[next] : t1;
    if (gsl_odeiv2_evolve_apply(evolve.get(), control.get(), step.get(), &sys, &t, target, &h, y) != GSL_SUCCESS)
      return false;
    if (stop >= 0 && y[stop] >= limit) {
      const double a = (limit - prev[stop]) / (y[stop] - prev[stop]);
      for (std::size_t i = 0; i < n; ++i) y[i] = prev[i] + a * (y[i] - prev[i]);
      t = t0 + a * (t - t0);
      return true;
    }
    while (next < at.size() && at[next] <= t) visit(at[next++], y);
  }
  return true;
}

// Integrates from the pole to the equator for the unknowns (Gamma, l0, p); eta is measured
// from the plate (0 at the contact edge), so the equator's eta is -eta_bar at a solution.
// `record` (if not null) receives (psi, l1, l2, theta, eta, half volume) at each psi of `at`.
Shot shoot(const Material& m, double gamma, double l0, double p, double tol, const std::vector<double>& at = {},
           std::vector<std::array<double, 6>>* record = nullptr) {
  Shot s;
  OdeParams P{m, p};
  double l1 = l0, l2 = l0;
  std::size_t next = 0;
  if (gamma > 0) {
    double psi = pole_start(gamma), y[3] = {l0, l0, 0.0};
    while (next < at.size() && at[next] <= psi) {
      if (record) record->push_back({at[next], l0, l0, 0.0, 0.0, 0.0});
      ++next;
    }
    if (!integrate(contact_rhs, 3, &P, psi, gamma, y, tol, -1, 0.0, at, next, [&](double a, const double* v) {
          if (record) record->push_back({a, v[0], v[1], 0.0, 0.0, 0.0});
        }))
      return s;
    l1 = y[0];
    l2 = y[1];
    s.energy = y[2];
  }
  s.l1c = l1;
  s.l2c = l2;
  double psi = gamma > 0 ? gamma : pole_start(1.0);
  // Without contact the pole is a free cap: theta starts at psi, as on a sphere.
  double y[6] = {l1, l2, gamma > 0 ? 0.0 : psi, 0.0, 0.0, s.energy};
  while (next < at.size() && at[next] <= psi) {
    if (record) record->push_back({at[next], y[0], y[1], y[2], y[3], y[4]});
    ++next;
  }
  // Recording the meridian needs every point up to the equator; the shooting stops at theta = pi/2.
  const int stop = record ? -1 : 2;
  if (!integrate(free_rhs, 6, &P, psi, M_PI / 2, y, tol, stop, M_PI / 2, at, next, [&](double a, const double* v) {
        if (record) record->push_back({a, v[0], v[1], v[2], v[3], v[4]});
      }))
    return s;
  s.ok = true;
  s.psi_end = psi;
  s.l1 = y[0];
  s.l2 = y[1];
  s.theta = y[2];
  s.eta = y[3];
  s.half_volume = y[4];
  s.energy = y[5];
  return s;
}

// The pole stretch l0 that makes the meridian vertical at the equator, for a given contact
// angle and pressure: Brent's method on Shot::condition (decreasing in l0), bracketed by
// stepping out from `guess`. Returns the shot there (ok = false when no bracket is found).
Shot shoot_to_equator(const Material& m, double gamma, double p, double guess, double scale, double tol, double& l0) {
  auto cond = [&](double l, Shot& s) {
    s = shoot(m, gamma, l, p, tol);
    return s.ok ? s.condition() : std::numeric_limits<double>::quiet_NaN();
  };
  Shot s;
  double a = guess, fa = cond(a, s);
  if (!std::isfinite(fa)) return Shot{};
  double d = scale, b = a, fb = fa;
  for (int i = 0; i < 60 && (fb > 0) == (fa > 0); ++i) {
    b = fa > 0 ? a + d : std::max(0.5 * a, a - d);  // too curled: stretch more
    fb = cond(b, s);
    if (!std::isfinite(fb)) return Shot{};
    if ((fb > 0) == (fa > 0)) {
      a = b;
      fa = fb;
      d *= 2;
    }
  }
  if ((fb > 0) == (fa > 0)) return Shot{};
  if (fa == 0) return l0 = a, shoot(m, gamma, a, p, tol);
  // Brent.
  struct Ctx { decltype(cond)* c; Shot* s; } ctx{&cond, &s};
  gsl_function F;
  F.function = [](double l, void* v) {
    auto* c = static_cast<Ctx*>(v);
    return (*c->c)(l, *c->s);
  };
  F.params = &ctx;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &F, std::min(a, b), std::max(a, b)) != GSL_SUCCESS) return Shot{};
  for (int it = 0; it < 200; ++it) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) return Shot{};
    const double lo = gsl_root_fsolver_x_lower(solver.get()), hi = gsl_root_fsolver_x_upper(solver.get());
    if (hi - lo <= 1e-15 * hi) break;
  }
  l0 = gsl_root_fsolver_root(solver.get());
  return shoot(m, gamma, l0, p, tol);
}

struct Problem {
  const Material* m;
  Fill fill;
  double eta_bar;  // target half gap / R0
  double volume;   // target volume / R0^3 (ConstantVolume)
  double p_fixed;  // pressure (ConstantPressure)
  double tol;
  double l0;       // the last pole stretch found (the next inner solve starts there)
  double scale;    // bracketing step of the pole stretch
};

// Unknowns u = (Gamma[, p]); the pole stretch solves the equator condition inside;
// residuals (eta_equator + eta_bar[, V/V_i - 1]).
int contact_residuals(const gsl_vector* u, void* params, gsl_vector* r) {
  auto* pr = static_cast<Problem*>(params);
  const double gamma = std::abs(gsl_vector_get(u, 0));
  const double p = pr->fill == Fill::ConstantVolume ? gsl_vector_get(u, 1) : pr->p_fixed;
  if (!(p > 0 && gamma < M_PI / 2)) return GSL_EDOM;
  double l0 = pr->l0;
  const Shot s = shoot_to_equator(*pr->m, gamma, p, pr->l0, pr->scale, pr->tol, l0);
  if (!s.ok) return GSL_EBADFUNC;
  pr->l0 = l0;
  gsl_vector_set(r, 0, s.eta + pr->eta_bar);
  if (pr->fill == Fill::ConstantVolume) gsl_vector_set(r, 1, 2 * s.half_volume / pr->volume - 1);
  return GSL_SUCCESS;
}

}  // namespace

InflatedMembrane::InflatedMembrane(const Sheet& sheet, double rest_radius, double inflation_pressure,
                                   MembraneContactOptions options)
    : sheet_(sheet), r0_(rest_radius), p_i_(inflation_pressure), options_(options) {
  validate(sheet, "inflated membrane");
  if (!(std::isfinite(r0_) && r0_ > 0)) throw UsageError("inflated membrane: the rest radius must be positive and finite");
  if (!(std::isfinite(p_i_) && p_i_ > 0))
    throw UsageError("inflated membrane: the inflation pressure must be positive and finite");
  l_i_ = sphere_stretch(sheet_, r0_, p_i_);
  gsl_errors_off();
}

double InflatedMembrane::inflated_volume() const { return 4.0 / 3.0 * M_PI * std::pow(inflated_radius(), 3); }
double InflatedMembrane::force_scale() const { return sheet_.stretching_modulus() * r0_; }

MembraneContact InflatedMembrane::free_state() const {
  MembraneContact s;
  const double Ri = inflated_radius(), T = sphere_tension(sheet_, l_i_);
  s.compression = 0;
  s.half_gap = Ri;
  s.contact_angle = 0;
  s.pole_stretch = l_i_;
  s.pressure = p_i_;
  s.contact_radius = 0;
  s.equator_radius = Ri;
  s.equator_tension = T;
  s.force = 0;
  s.equator_force = p_i_ * M_PI * Ri * Ri - 2 * M_PI * Ri * T;
  s.volume = inflated_volume();
  s.energy = 4 * M_PI * r0_ * r0_ * sheet_.stretching_modulus() * std::pow(l_i_ * l_i_ - 1, 2) / (4 * (1 - sheet_.poisson_ratio));
  return s;
}

MembraneContact InflatedMembrane::solve(double X, Fill fill, const MembraneContact& guess) const {
  if (!(X > 0 && X < 1)) throw UsageError("inflated membrane: the compression must be in (0, 1)");
  const Material m{sheet_.poisson_ratio, 0.5 / (1 - sheet_.poisson_ratio * sheet_.poisson_ratio)};
  const double Y = sheet_.stretching_modulus();
  double gamma = guess.contact_angle, l0 = guess.pole_stretch, p = guess.pressure * r0_ / Y;
  // Off the free sphere: the contact angle of a truncated sphere of the inflated radius.
  if (gamma <= 0) gamma = std::asin(std::min(0.9, std::sqrt(2 * X)));
  Problem pr{&m, fill, (1 - X) * l_i_, 4.0 / 3.0 * M_PI * l_i_ * l_i_ * l_i_, p_i_ * r0_ / Y, options_.ode_tolerance,
             l0, 1e-3 * (l_i_ - 1.0)};
  const std::size_t n = fill == Fill::ConstantVolume ? 2 : 1;
  gsl_multiroot_function f{contact_residuals, n, &pr};
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> u(gsl_vector_alloc(n), gsl_vector_free);
  gsl_vector_set(u.get(), 0, gamma);
  if (n == 2) gsl_vector_set(u.get(), 1, p);
  std::unique_ptr<gsl_multiroot_fsolver, decltype(&gsl_multiroot_fsolver_free)> solver(
      gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, n), gsl_multiroot_fsolver_free);
  auto fail = [&](const std::string& why) {
    std::ostringstream msg;
    msg << "inflated membrane: no solution at compression X = " << X << " (" << why << ")";
    return ComputationError(msg.str());
  };
  if (gsl_multiroot_fsolver_set(solver.get(), &f, u.get()) != GSL_SUCCESS) throw fail("the first guess does not integrate");
  int status = GSL_CONTINUE;
  for (int it = 0; it < options_.max_iterations && status == GSL_CONTINUE; ++it) {
    if (gsl_multiroot_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
    status = gsl_multiroot_test_residual(solver.get()->f, options_.root_tolerance);
  }
  if (status != GSL_SUCCESS) throw fail("the root finder did not converge");
  const gsl_vector* x = gsl_multiroot_fsolver_root(solver.get());
  gamma = std::abs(gsl_vector_get(x, 0));
  if (n == 2) p = gsl_vector_get(x, 1);
  else p = pr.p_fixed;
  const Shot s = shoot_to_equator(m, gamma, p, pr.l0, pr.scale, options_.ode_tolerance, l0);
  if (!s.ok) throw fail("the solution does not integrate");

  MembraneContact out;
  out.compression = X;
  out.half_gap = pr.eta_bar * r0_;
  out.contact_angle = gamma;
  out.pole_stretch = l0;
  out.pressure = p * Y / r0_;
  out.contact_radius = s.l2c * std::sin(gamma) * r0_;
  out.equator_radius = s.l2 * r0_;
  out.equator_tension = m.T1(s.l1, s.l2) * Y;
  out.force = out.pressure * M_PI * out.contact_radius * out.contact_radius;
  out.equator_force = out.pressure * M_PI * out.equator_radius * out.equator_radius -
                      2 * M_PI * out.equator_radius * out.equator_tension * std::sin(s.theta);
  out.volume = 2 * s.half_volume * r0_ * r0_ * r0_;
  out.energy = 2 * s.energy * Y * r0_ * r0_;
  double res = std::abs(s.condition());
  for (std::size_t i = 0; i < n; ++i) res = std::max(res, std::abs(gsl_vector_get(solver.get()->f, i)));
  out.residual = res;
  return out;
}

std::vector<MembraneContact> InflatedMembrane::sweep(const std::vector<double>& compressions, Fill fill) const {
  std::vector<MembraneContact> out;
  MembraneContact last = free_state();
  for (double target : compressions) {
    if (!(target > last.compression && target < 1))
      throw UsageError("inflated membrane: compressions must increase within (0, 1)");
    double step = std::min(options_.max_step, target - last.compression);
    while (last.compression < target) {
      const double X = std::min(target, last.compression + step);
      try {
        last = solve(X, fill, last);
      } catch (const ComputationError&) {
        step *= 0.5;
        if (step < 1e-6 * options_.max_step) throw;
      }
    }
    out.push_back(last);
  }
  return out;
}

std::vector<MeridianPoint> InflatedMembrane::meridian(const MembraneContact& st, int n) const {
  if (n < 1) throw UsageError("inflated membrane: the meridian needs n >= 1");
  const Material m{sheet_.poisson_ratio, 0.5 / (1 - sheet_.poisson_ratio * sheet_.poisson_ratio)};
  const double Y = sheet_.stretching_modulus(), p = st.pressure * r0_ / Y;
  std::vector<double> at;
  for (int i = 0; i <= n; ++i) at.push_back(std::max(pole_start(1.0), M_PI / 2 * i / n));
  std::vector<std::array<double, 6>> rec;
  const Shot s = shoot(m, st.contact_angle, st.pole_stretch, p, options_.ode_tolerance, at, &rec);
  if (!s.ok || rec.size() != at.size()) throw ComputationError("inflated membrane: the meridian does not integrate");
  std::vector<MeridianPoint> out;
  for (const auto& r : rec) {
    MeridianPoint q;
    q.psi = r[0];
    q.lambda1 = r[1];
    q.lambda2 = r[2];
    q.theta = r[3];
    q.rho = r[2] * std::sin(r[0]) * r0_;
    q.eta = st.half_gap + r[4] * r0_;
    q.tension1 = m.T1(r[1], r[2]) * Y;
    q.tension2 = m.T2(r[1], r[2]) * Y;
    q.vertical_force = st.pressure * M_PI * q.rho * q.rho - 2 * M_PI * q.rho * q.tension1 * std::sin(q.theta);
    out.push_back(q);
  }
  return out;
}

}  // namespace cmp::elasticity
