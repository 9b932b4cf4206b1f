#include "shell/relax.hpp"

#include <Eigen/Eigenvalues>

#include "core/errors.hpp"
#include "core/thread_governor.hpp"
#include "mesh/edge_topology.hpp"
#include "shell/element_assembly.hpp"
#include "shell/volume_constraint.hpp"
#include "shell/volume_rule.hpp"
#include "shell/volume_update_window.hpp"

#include <cmath>
#include <optional>

namespace cmp::shell {

void RelaxParameters::validate() const {
  fire.validate();
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("relax: ") + what);
  };
  require(relative_tolerance > 0 && std::isfinite(relative_tolerance), "the relative force tolerance must be positive");
  require(force_scale > 0 && std::isfinite(force_scale), "the force scale must be positive");
  require(mass_factor > 0 && std::isfinite(mass_factor), "the mass factor must be positive");
  require(volume_tolerance > 0, "the volume tolerance must be positive");
  require(max_volume_updates >= 0, "the number of volume updates must not be negative");
  require(volume_update_factor >= 1, "the volume update factor must be at least 1");
  require(volume_update_interval >= 1, "the volume update interval must be at least 1");
}

double default_force_scale(const mesh::TriMesh& rest, double youngs_modulus, double thickness) {
  const auto topo = mesh::edge_topology(rest.F);
  double sum = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e)
    sum += (rest.V.row(topo.edges(e, 1)) - rest.V.row(topo.edges(e, 0))).norm();
  const double mean = topo.edges.rows() > 0 ? sum / static_cast<double>(topo.edges.rows()) : 1.0;
  return youngs_modulus * thickness * mean;
}

std::string relax_stop_name(RelaxStop stop) {
  switch (stop) {
    case RelaxStop::Converged: return "converged";
    case RelaxStop::MaxIterations: return "max_iterations";
    case RelaxStop::VolumeUpdates: return "volume_updates";
    case RelaxStop::Interrupted: return "interrupted";
  }
  return "?";
}

double stiffest_mode(const ShellSystem& s, const Eigen::VectorXd& x, int steps) {
  const Eigen::Index n = x.size();
  // A deterministic start with every component (fixed vertices masked out).
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = std::sin(1.0 + 0.7 * static_cast<double>(i)) + 0.1;
  for (long k = 0; k < s.vertex_count(); ++k)
    if (s.fixed()[k]) v.segment<3>(3 * k).setZero();
  double scale = 0;
  for (Eigen::Index i = 0; i < n; ++i) scale = std::max(scale, std::abs(x[i]));
  const double eps = 1e-7 * std::max(scale, 1e-300);
  const double norm = v.norm();
  if (!(norm > 0)) return 0;
  v /= norm;
  // Lanczos: the Krylov space of H from v, as the tridiagonal T (alpha on the diagonal, beta
  // beside it); T's largest eigenvalue approaches H's far faster than a power iteration's
  // Rayleigh quotient (12 steps of it come closer than 30 power steps: each step is two force
  // evaluations, and one such estimate precedes every relaxation).
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(n), fp(n), fm(n), w(n);
  std::vector<double> alpha, beta;
  ThreadGovernor governor;  // one thread or all, whichever is faster now (same bits either way)
  for (int j = 0; j < steps; ++j, governor.tick()) {
    s.forces(x + eps * v, fp);
    s.forces(x - eps * v, fm);
    w = (fm - fp) / (2 * eps);  // H v = -(dF/dx) v
    const double a = v.dot(w);
    alpha.push_back(a);
    w -= a * v;
    if (j > 0) w -= beta.back() * previous;
    const double b = w.norm();
    if (!(b > 1e-12 * std::abs(a)) || j + 1 == steps) break;
    beta.push_back(b);
    previous = v;
    v = w / b;
  }
  const Eigen::Index m = static_cast<Eigen::Index>(alpha.size());
  Eigen::VectorXd diagonal = Eigen::Map<const Eigen::VectorXd>(alpha.data(), m);
  Eigen::VectorXd off = m > 1 ? Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(beta.data(), m - 1)) : Eigen::VectorXd();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
  return std::abs(solver.eigenvalues().cwiseAbs().maxCoeff());
}

namespace {

// One FIRE run on s.x; adds to r. With a constant-volume pressure, Pi moves inside it (relax.hpp).
void fire_once(ShellSystem& s, const RelaxParameters& p, double mass, RelaxResult& r, const RelaxProgress& progress,
               VolumeRule& rule) {
  minimise::FireParameters fp = p.fire;
  fp.force_tolerance = p.relative_tolerance * p.force_scale;
  fp.mass = mass;
  // FIRE's vector passes on all threads only where the force passes are (a vertex has about
  // two triangles): below that they are a few microseconds, less than a fork/join.
  fp.parallel_size = std::max<long>(fp.parallel_size, 3 * ElementAssembly::parallel_elements() / 2);
  const long before = r.iterations;
  TurgorPressure* pressure = s.pressure();
  minimise::FireAdjust adjust;
  VolumeUpdateWindow window(fp.force_tolerance, p.volume_update_factor, p.volume_update_interval);
  std::optional<VolumeConstraint> constraint;
  minimise::FireConstraint constrain;
  if (pressure && pressure->control() == PressureControl::ConstantVolume && p.volume_rule == VolumeRuleKind::Projected &&
      p.holds_volume()) {
    constraint.emplace(*pressure, s.fixed());
    constrain = [&](Eigen::VectorXd& y, Eigen::VectorXd& v) { constraint->project(y, v); };
  } else if (pressure && pressure->control() == PressureControl::ConstantVolume) {
    adjust = [&, pressure](long it, double max_force) {
      if (r.volume_updates >= p.max_volume_updates || !window.open(it, max_force)) return false;
      const double error = pressure->volume_error(span_of(s.x));
      if (!(error > p.volume_tolerance)) return false;
      rule.update(*pressure, span_of(s.x));
      window.moved(max_force, error);
      ++r.volume_updates;
      return true;
    };
  }
  const auto res = minimise::fire(
      s.x,
      [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
        if (!constraint) return s.forces(y, f);
        s.forces_without(pressure, y, f);
        constraint->project_force(y, f);
      },
      fp, [&](long it, double max_force) { return !progress || progress(before + it, max_force / p.force_scale); },
      200, adjust, constrain);
  r.iterations += res.iterations;
  r.force_evaluations += res.force_evaluations;
  r.residual = res.max_force / p.force_scale;
  r.stop = res.stop == minimise::FireStop::ForceTolerance ? RelaxStop::Converged
           : res.stop == minimise::FireStop::Interrupted  ? RelaxStop::Interrupted
                                                           : RelaxStop::MaxIterations;
}

}  // namespace

RelaxResult relax(ShellSystem& s, const RelaxParameters& p, const RelaxProgress& progress) {
  p.validate();
  // Velocity Verlet is stable for dt < 2 sqrt(m / lambda_max): dt_max = 1.5 needs
  // m > 0.5625 lambda_max; m = lambda_max leaves a margin of 1.33 in dt for stiffening.
  const double lambda = stiffest_mode(s, s.x);
  const double mass = p.mass_factor * std::max(lambda, 1e-300) * (p.fire.dt_max * p.fire.dt_max / 2.25);
  RelaxResult r;
  VolumeRule rule(p.volume_rule);
  fire_once(s, p, mass, r, progress, rule);
  TurgorPressure* pressure = s.pressure();
  if (!pressure || pressure->control() != PressureControl::ConstantVolume || !r.converged()) return r;
  r.volume_error = pressure->volume_error(span_of(s.x));
  // FIRE converged with a volume off only when the updates ran out: the thesis's loop.
  while (r.volume_error > p.volume_tolerance) {
    if (r.volume_updates >= p.max_volume_updates) {
      r.stop = RelaxStop::VolumeUpdates;
      return r;
    }
    rule.update(*pressure, span_of(s.x));
    ++r.volume_updates;
    fire_once(s, p, mass, r, progress, rule);
    if (!r.converged()) return r;
    r.volume_error = pressure->volume_error(span_of(s.x));
  }
  return r;
}

void heun_step(ShellSystem& s, double dt, double damping) {
  Eigen::VectorXd k1, k2;
  s.forces(s.x, k1);
  const double h = dt / damping;
  s.forces(s.x + h * k1, k2);
  s.x += 0.5 * h * (k1 + k2);
}

HeunResult heun_relax(ShellSystem& s, double dt, double damping, double relative_tolerance, double force_scale,
                      long max_steps) {
  HeunResult r;
  Eigen::VectorXd f;
  // One thread or all, whichever runs faster now (the force passes give the same bits either way).
  ThreadGovernor governor;
  for (;; ++r.steps, governor.tick()) {
    s.forces(s.x, f);
    r.residual = minimise::max_block_norm(f, 3) / force_scale;
    if (!std::isfinite(r.residual))
      throw ComputationError("heun: non-finite force after " + std::to_string(r.steps) + " steps (time step too large?)");
    if (r.residual <= relative_tolerance) {
      r.converged = true;
      return r;
    }
    if (r.steps >= max_steps) return r;
    heun_step(s, dt, damping);
  }
}

}  // namespace cmp::shell
