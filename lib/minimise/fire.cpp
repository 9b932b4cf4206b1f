#include "minimise/fire.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::minimise {

void FireParameters::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("FIRE: ") + what);
  };
  require(dt > 0 && std::isfinite(dt), "dt must be positive");
  require(dt_max >= dt, "dt_max must be at least dt");
  require(alpha_start > 0 && alpha_start < 1, "alpha_start must lie in (0, 1)");
  require(n_min >= 0, "n_min must not be negative");
  require(f_alpha > 0 && f_alpha <= 1, "f_alpha must lie in (0, 1]");
  require(f_inc >= 1, "f_inc must be at least 1");
  require(f_dec > 0 && f_dec < 1, "f_dec must lie in (0, 1)");
  require(mass > 0, "mass must be positive");
  require(force_tolerance >= 0, "force tolerance must not be negative");
  require(max_iterations > 0, "max_iterations must be positive");
  require(block_size > 0, "block_size must be positive");
}

std::string fire_stop_name(FireStop stop) {
  switch (stop) {
    case FireStop::ForceTolerance: return "force_tolerance";
    case FireStop::MaxIterations: return "max_iterations";
    case FireStop::Interrupted: return "interrupted";
  }
  return "?";
}

double max_block_norm(const Eigen::VectorXd& f, int block_size) {
  double worst = 0;
  for (Eigen::Index i = 0; i + block_size <= f.size(); i += block_size) {
    const double n2 = f.segment(i, block_size).squaredNorm();
    if (std::isnan(n2)) return n2;  // a NaN force must never pass for converged
    worst = std::max(worst, n2);
  }
  return std::sqrt(worst);
}

FireResult fire(Eigen::VectorXd& x, const ForceFunction& forces, const FireParameters& p,
                const FireProgress& progress, long progress_every) {
  p.validate();
  if (x.size() % p.block_size != 0) throw UsageError("FIRE: state size is not a multiple of the block size");
  FireResult result;
  Eigen::VectorXd f(x.size()), v = Eigen::VectorXd::Zero(x.size());
  forces(x, f);
  result.force_evaluations = 1;
  double dt = p.dt, alpha = p.alpha_start;
  long last_cut = 0;
  const double half_dt_over_m = 0.5 / p.mass;
  for (long it = 0;; ++it) {
    result.max_force = max_block_norm(f, p.block_size);
    result.iterations = it;
    if (!std::isfinite(result.max_force))
      throw ComputationError("FIRE: non-finite force after " + std::to_string(it) + " iterations");
    if (result.max_force <= p.force_tolerance) { result.stop = FireStop::ForceTolerance; return result; }
    if (it >= p.max_iterations) { result.stop = FireStop::MaxIterations; return result; }
    if (progress && it > 0 && it % progress_every == 0 && !progress(it, result.max_force)) {
      result.stop = FireStop::Interrupted;
      return result;
    }
    // Velocity Verlet step.
    v += (dt * half_dt_over_m) * f;
    x += dt * v;
    forces(x, f);
    ++result.force_evaluations;
    v += (dt * half_dt_over_m) * f;
    // FIRE: mix the velocity towards the force, adapt dt and alpha.
    const double power = v.dot(f);
    const double v_norm = v.norm(), f_norm = f.norm();
    if (f_norm > 0) v = (1 - alpha) * v + (alpha * v_norm / f_norm) * f;
    if (power > 0) {
      if (it - last_cut > p.n_min) {
        dt = std::min(dt * p.f_inc, p.dt_max);
        alpha *= p.f_alpha;
      }
    } else {
      v.setZero();
      last_cut = it;
      dt *= p.f_dec;
      alpha = p.alpha_start;
    }
  }
}

}  // namespace cmp::minimise
