// Macroscopic observables of the solver's state (lbm/flow_solver.hpp): kappa, tortuosity and
// the other FlowObservables, and the velocity and density fields for VTK output.
#include "lbm/flow_solver_state.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::lbm {

// Pre-collision populations of a node at the current step count.
template <class Real>
void FlowSolver::Impl::gather(const BigVector<Real>& F, long node, double f[kQ]) const {
  for (int q = 0; q < kQ; ++q) f[q] = load_population(F.data(), incoming_slot(q, node, (steps & 1) == 0));
}

template <class Real>
FlowObservables FlowSolver::Impl::observe() const {
  const BigVector<Real>& F = const_cast<Impl*>(this)->pops<Real>();
  const int a = settings.axis;
  struct Part {
    double ua = 0, speed = 0, mass = 0, max_speed = 0;
  };
  std::vector<Part> parts(static_cast<std::size_t>(chunks));
  const double half[3] = {0.5 * force[0], 0.5 * force[1], 0.5 * force[2]};
  for_each_chunk(chunks, [&](int c) {
    Part p;
    const long end = std::min(chunk_start(c + 1), fluid);
    for (long i = chunk_start(c); i < end; ++i) {
      double f[kQ];
      gather(F, i, f);
      double rho = 0, u[3] = {0, 0, 0};
      for (int q = 0; q < kQ; ++q) {
        rho += f[q];
        u[0] += kCx[q] * f[q];
        u[1] += kCy[q] * f[q];
        u[2] += kCz[q] * f[q];
      }
      for (int d = 0; d < 3; ++d) u[d] += half[d];
      const double s = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      p.ua += u[a];
      p.speed += s;
      p.mass += rho;
      p.max_speed = std::max(p.max_speed, s);
    }
    parts[static_cast<std::size_t>(c)] = p;
  });
  Part t;
  for (const Part& p : parts) {
    t.ua += p.ua;
    t.speed += p.speed;
    t.mass += p.mass;
    t.max_speed = std::max(t.max_speed, p.max_speed);
  }
  FlowObservables o;
  o.steps = steps;
  const double box = static_cast<double>(n[0]) * n[1] * n[2];
  o.superficial_velocity = t.ua / box;
  o.interstitial_velocity = t.ua / static_cast<double>(fluid);
  o.max_speed = t.max_speed;
  o.pressure_gradient = grad_p;
  o.kappa_lu = nu * o.superficial_velocity / grad_p;
  o.tortuosity = t.speed / t.ua;
  o.reynolds = o.superficial_velocity * std::sqrt(std::abs(o.kappa_lu)) / nu;
  o.mach = t.max_speed / std::sqrt(kCs2);
  o.mass = t.mass;
  return o;
}

FlowObservables FlowSolver::observe() const {
  return impl_->settings.precision == Precision::kFloat ? impl_->observe<float>() : impl_->observe<double>();
}

std::vector<double> FlowSolver::velocity_field() const {
  const Impl& m = *impl_;
  std::vector<double> out(static_cast<std::size_t>(3L * m.n[0] * m.n[1] * m.n[2]), 0.0);
  for (long i = 0; i < m.fluid; ++i) {
    double f[kQ];
    if (m.settings.precision == Precision::kFloat) m.gather(m.ff, i, f);
    else m.gather(m.fd, i, f);
    double u[3] = {0, 0, 0};
    for (int q = 0; q < kQ; ++q) {
      u[0] += kCx[q] * f[q];
      u[1] += kCy[q] * f[q];
      u[2] += kCz[q] * f[q];
    }
    const std::size_t s = static_cast<std::size_t>(m.site[static_cast<std::size_t>(i)]);
    for (int d = 0; d < 3; ++d) out[3 * s + d] = u[d] + 0.5 * m.force[d];
  }
  return out;
}

std::vector<double> FlowSolver::density_field() const {
  const Impl& m = *impl_;
  std::vector<double> out(static_cast<std::size_t>(m.n[0]) * m.n[1] * m.n[2], 0.0);
  for (long i = 0; i < m.fluid; ++i) {
    double f[kQ];
    if (m.settings.precision == Precision::kFloat) m.gather(m.ff, i, f);
    else m.gather(m.fd, i, f);
    double rho = 0;
    for (int q = 0; q < kQ; ++q) rho += f[q];
    out[static_cast<std::size_t>(m.site[static_cast<std::size_t>(i)])] = rho;
  }
  return out;
}

}  // namespace cmp::lbm
