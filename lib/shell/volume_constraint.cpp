#include "shell/volume_constraint.hpp"

#include "shell/element_assembly.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::shell {

VolumeConstraint::VolumeConstraint(TurgorPressure& pressure, const std::vector<char>& fixed)
    : pressure_(pressure),
      fixed_(fixed),
      norm2_(static_cast<std::size_t>(pressure.shell_count()), 0.0),
      chunks_(static_cast<int>(std::max<long>(1, (pressure.vertex_count() + kChunkVertices - 1) / kChunkVertices))),
      parallel_(ElementAssembly::runs_parallel(2 * pressure.vertex_count())),
      partial_(static_cast<std::size_t>(chunks_)) {}

void VolumeConstraint::per_shell_dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                     std::vector<double>& out) const {
  const std::vector<int>& shell = pressure_.vertex_shells();
  const long n = static_cast<long>(shell.size());
  // Per chunk, then added in chunk order: the same bits on any thread count.
  for_each_chunk(chunks_, parallel_, [&](int c) {
    std::vector<double>& sum = partial_[static_cast<std::size_t>(c)];
    sum.assign(norm2_.size(), 0.0);
    // A shell's vertices mostly follow each other: its running sum stays in a register until
    // the shell changes (the same additions in the same order).
    int current = -1;
    double running = 0;
    for (long v = chunk_begin(n, chunks_, c), end = chunk_begin(n, chunks_, c + 1); v < end; ++v) {
      if (shell[v] != current) {
        if (current >= 0) sum[current] = running;
        current = shell[v];
        running = sum[current];
      }
      running += a[3 * v] * b[3 * v] + a[3 * v + 1] * b[3 * v + 1] + a[3 * v + 2] * b[3 * v + 2];
    }
    if (current >= 0) sum[current] = running;
  });
  out.assign(norm2_.size(), 0.0);
  for (const std::vector<double>& sum : partial_)
    for (std::size_t s = 0; s < out.size(); ++s) out[s] += sum[s];
}

void VolumeConstraint::add_along_normals(const std::vector<double>& coefficient, Eigen::VectorXd& y,
                                         double sign) const {
  const std::vector<int>& shell = pressure_.vertex_shells();
  const long n = static_cast<long>(shell.size());
  for_each_chunk(chunks_, parallel_, [&](int c) {
    for (long v = chunk_begin(n, chunks_, c), end = chunk_begin(n, chunks_, c + 1); v < end; ++v) {
      const double k = sign * coefficient[shell[v]];
      for (int a = 0; a < 3; ++a) y[3 * v + a] += k * n_[3 * v + a];
    }
  });
}

void VolumeConstraint::gradients(const Eigen::VectorXd& x) {
  n_.resize(x.size());
  pressure_.volume_gradient({x.data(), static_cast<std::size_t>(x.size())}, {n_.data(), static_cast<std::size_t>(n_.size())});
  for (std::size_t v = 0; v < fixed_.size(); ++v)
    if (fixed_[v]) n_.segment<3>(3 * static_cast<Eigen::Index>(v)).setZero();
  per_shell_dot(n_, n_, norm2_);
  have_gradients_ = true;
}

void VolumeConstraint::remove_normal(Eigen::VectorXd& y, std::vector<double>& coefficient) const {
  per_shell_dot(y, n_, coefficient);
  for (std::size_t s = 0; s < coefficient.size(); ++s) coefficient[s] = norm2_[s] > 0 ? coefficient[s] / norm2_[s] : 0.0;
  add_along_normals(coefficient, y, -1.0);
}

void VolumeConstraint::project(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  const std::vector<double>& target = pressure_.target_volumes();
  const auto step_onto_targets = [&](const std::vector<double>& volume) {
    for (std::size_t s = 0; s < scratch_.size(); ++s) scratch_[s] = norm2_[s] > 0 ? (target[s] - volume[s]) / norm2_[s] : 0.0;
    add_along_normals(scratch_, x);
  };
  scratch_.resize(norm2_.size());
  const std::span<const double> state(x.data(), static_cast<std::size_t>(x.size()));
  if (have_gradients_) {
    step_onto_targets(pressure_.volumes(state));
  } else {
    for (int k = 0;; ++k) {
      gradients(x);
      const std::vector<double> volume = pressure_.volumes(state);
      double worst = 0;
      for (std::size_t s = 0; s < volume.size(); ++s)
        if (norm2_[s] > 0) worst = std::max(worst, std::abs(volume[s] - target[s]) / target[s]);
      if (worst <= kTolerance) break;
      if (k == kNewtonSteps || !std::isfinite(worst))
        throw ComputationError("volume constraint: the volumes are still " + std::to_string(worst) +
                               " off their targets after " + std::to_string(k) + " Newton steps");
      step_onto_targets(volume);
    }
  }
  remove_normal(v, scratch_);
}

void VolumeConstraint::project_force(const Eigen::VectorXd& x, Eigen::VectorXd& f) {
  gradients(x);
  remove_normal(f, scratch_);
  // f was f_other; it is now f_other - c_s n_s: the total force at Pi_s = -c_s.
  for (double& c : scratch_) c = -c;
  pressure_.set_turgors(scratch_);
}

}  // namespace cmp::shell
