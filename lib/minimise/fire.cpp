#include "minimise/fire.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"
#include "core/thread_governor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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
  require(divergence_factor == 0 || divergence_factor > 1, "divergence_factor must be 0 (off) or above 1");
  require(dt_max_recovery >= 0, "dt_max_recovery must not be negative");
  require(mass > 0, "mass must be positive");
  require(force_tolerance >= 0, "force tolerance must not be negative");
  require(parallel_size >= 0, "parallel_size must not be negative");
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
                const FireProgress& progress, long progress_every, const FireAdjust& adjust,
                const FireConstraint& constrain) {
  p.validate();
  if (x.size() % p.block_size != 0) throw UsageError("FIRE: state size is not a multiple of the block size");
  FireResult result;
  const Eigen::Index n = x.size();
  Eigen::VectorXd f(n), v = Eigen::VectorXd::Zero(n);
  if (constrain) constrain(x, v);
  forces(x, f);
  result.force_evaluations = 1;
  double dt = p.dt, alpha = p.alpha_start, dt_max = p.dt_max;
  long last_cut = 0, last_ringing = 0;
  const double inverse_mass = 1.0 / p.mass;
  // The velocity update before each drift, v <- keep v + (mix + dt/2m) f: the FIRE mixing of
  // the last step fused with the first half kick of this one (two passes over the state per
  // iteration instead of eight). At the start v = 0, so keep is 0.
  double keep = 0, mix = 0;
  // Large states are cut into a fixed number of chunks of whole blocks, passed over by all
  // threads; small ones are one chunk (an iteration too short for a fork/join).
  const int chunks = n >= kParallelFireSize ? kFireChunks : 1;
  const bool parallel = chunks > 1 && n >= p.parallel_size;
  std::vector<Eigen::Index> bounds(chunks + 1);
  for (int c = 0; c <= chunks; ++c) bounds[c] = chunk_begin(n, chunks, c, p.block_size);
  std::vector<std::array<double, 4>> sums(chunks);
  // One thread or all, whichever runs faster now (another process may hold a core); the
  // result is the same either way.
  ThreadGovernor governor(chunks > 1 ? 0 : 1);
  result.max_force = max_block_norm(f, p.block_size);
  for (long it = 0;; ++it, governor.tick()) {
    result.iterations = it;
    if (adjust && adjust(it, result.max_force)) {
      forces(x, f);
      ++result.force_evaluations;
      result.max_force = max_block_norm(f, p.block_size);
    }
    if (!std::isfinite(result.max_force))
      throw ComputationError("FIRE: non-finite force after " + std::to_string(it) + " iterations");
    if (result.max_force <= p.force_tolerance) { result.stop = FireStop::ForceTolerance; return result; }
    if (it >= p.max_iterations) { result.stop = FireStop::MaxIterations; return result; }
    if (progress && it > 0 && it % progress_every == 0 && !progress(it, result.max_force)) {
      result.stop = FireStop::Interrupted;
      return result;
    }
    const double force_before = result.max_force;
    // Mixing (previous step) and half kick, then drift.
    const double kick = 0.5 * dt * inverse_mass;
    const double cf = mix + kick;
    double* vp = v.data();
    double* xp = x.data();
    const double* fp = f.data();
    const auto drift = [&](int c) {
      for (Eigen::Index k = bounds[c]; k < bounds[c + 1]; ++k) {
        vp[k] = keep * vp[k] + cf * fp[k];
        xp[k] += dt * vp[k];
      }
    };
    // Second half kick, with the power P = v.F, |v|^2, |F|^2 and the largest |f_i| in one pass;
    // per chunk, then added in chunk order (the same sums for any thread count).
    const auto kick_and_measure = [&](int c) {
      double power = 0, vv = 0, ff = 0, worst = 0;
      for (Eigen::Index k = bounds[c]; k < bounds[c + 1]; k += p.block_size) {
        double block = 0;
        for (int b = 0; b < p.block_size; ++b) {
          const double fk = fp[k + b];
          const double vk = vp[k + b] + kick * fk;
          vp[k + b] = vk;
          power += vk * fk, vv += vk * vk, block += fk * fk;
        }
        ff += block;
        worst = std::max(worst, block);
        if (std::isnan(block)) { worst = block; break; }  // reported above as a non-finite force
      }
      sums[c] = {power, vv, ff, worst};
    };
    for_each_chunk(chunks, parallel, drift);
    if (constrain) constrain(x, v);
    forces(x, f);
    ++result.force_evaluations;
    for_each_chunk(chunks, parallel, kick_and_measure);
    double power = 0, vv = 0, ff = 0, worst = 0;
    for (int c = 0; c < chunks; ++c) {
      power += sums[c][0], vv += sums[c][1], ff += sums[c][2];
      worst = std::isnan(sums[c][3]) || std::isnan(worst) ? std::nan("") : std::max(worst, sums[c][3]);
    }
    result.max_force = std::sqrt(worst);
    const bool ringing = p.divergence_factor > 0 && force_before > 0 &&
                         result.max_force > p.divergence_factor * force_before;
    if (ringing) {
      ++result.divergence_restarts;
      last_ringing = it;
      dt_max = std::min(dt_max, 0.5 * dt);
    }
    // FIRE: turn v towards F (applied in the next pass), adapt dt and alpha.
    keep = 1 - alpha;
    mix = ff > 0 ? alpha * std::sqrt(vv / ff) : 0.0;
    if (power > 0 && !ringing) {
      if (p.dt_max_recovery > 0 && dt_max < p.dt_max && it - last_ringing > p.dt_max_recovery)
        dt_max = std::min(p.dt_max, dt_max * p.f_inc);
      if (it - last_cut > p.n_min) {
        dt = std::min(dt * p.f_inc, dt_max);
        alpha *= p.f_alpha;
      }
    } else {
      keep = mix = 0;  // restart from rest
      last_cut = it;
      dt *= p.f_dec;
      alpha = p.alpha_start;
    }
  }
}

}  // namespace cmp::minimise
