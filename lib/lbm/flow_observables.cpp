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
  // One part per slab, added in slab order (on several ranks every rank adds all ranks' parts
  // in that order): the same bits for any thread and rank count.
  const int own_slabs = static_cast<int>(slab_start.size()) - 1;
  std::vector<double> parts(4 * static_cast<std::size_t>(own_slabs));
  const double half[3] = {0.5 * force[0], 0.5 * force[1], 0.5 * force[2]};
  for_each_chunk(own_slabs, [&](int k) {
    Part p;
    for (long i = slab_start[static_cast<std::size_t>(k)]; i < slab_start[static_cast<std::size_t>(k) + 1]; ++i) {
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
    const double v[4] = {p.ua, p.speed, p.mass, p.max_speed};
    std::copy(v, v + 4, parts.begin() + 4 * k);
  });
  const std::vector<double> all = comm.all_gather(parts);
  Part t;
  for (std::size_t k = 0; k + 3 < all.size(); k += 4) {
    t.ua += all[k];
    t.speed += all[k + 1];
    t.mass += all[k + 2];
    t.max_speed = std::max(t.max_speed, all[k + 3]);
  }
  FlowObservables o;
  o.steps = steps;
  const double box = static_cast<double>(n[0]) * n[1] * n[2];
  o.superficial_velocity = t.ua / box;
  o.interstitial_velocity = t.ua / static_cast<double>(global_fluid);
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

// The fields: this rank's nodes as (site, ux, uy, uz, rho) records, gathered on rank 0.
std::vector<double> FlowSolver::Impl::field_records() const {
  std::vector<double> r(5 * static_cast<std::size_t>(fluid));
  for (long i = 0; i < fluid; ++i) {
    double f[kQ];
    if (settings.precision == Precision::kFloat) gather(ff, i, f);
    else gather(fd, i, f);
    double rho = 0, u[3] = {0, 0, 0};
    for (int q = 0; q < kQ; ++q) {
      rho += f[q];
      u[0] += kCx[q] * f[q];
      u[1] += kCy[q] * f[q];
      u[2] += kCz[q] * f[q];
    }
    double* o = r.data() + 5 * i;
    o[0] = static_cast<double>(site[static_cast<std::size_t>(i)]);
    for (int d = 0; d < 3; ++d) o[1 + d] = u[d] + 0.5 * force[d];
    o[4] = rho;
  }
  return comm.gather_to_root(r);
}

std::vector<double> FlowSolver::velocity_field() const {
  const Impl& m = *impl_;
  const std::vector<double> records = m.field_records();
  if (!m.comm.root()) return {};
  std::vector<double> out(static_cast<std::size_t>(3L * m.n[0] * m.n[1] * m.n[2]), 0.0);
  for (std::size_t k = 0; k < records.size(); k += 5) {
    const std::size_t s = static_cast<std::size_t>(records[k]);
    for (int d = 0; d < 3; ++d) out[3 * s + d] = records[k + 1 + d];
  }
  return out;
}

std::vector<double> FlowSolver::density_field() const {
  const Impl& m = *impl_;
  const std::vector<double> records = m.field_records();
  if (!m.comm.root()) return {};
  std::vector<double> out(static_cast<std::size_t>(m.n[0]) * m.n[1] * m.n[2], 0.0);
  for (std::size_t k = 0; k < records.size(); k += 5) out[static_cast<std::size_t>(records[k])] = records[k + 4];
  return out;
}

}  // namespace cmp::lbm
