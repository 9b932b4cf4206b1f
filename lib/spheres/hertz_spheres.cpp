#include "spheres/hertz_spheres.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"
#include "neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace cmp::spheres {

HertzSpheres::HertzSpheres(const Eigen::Vector3d& box, const Eigen::VectorXd& radii, const HertzMaterial& material,
                           double skin)
    : box_(box), inverse_box_(box.cwiseInverse()), material_(material), skin_fraction_(skin) {
  if (!(box.minCoeff() > 0) || !box.allFinite()) throw UsageError("box sides must be positive");
  if (!(skin >= 0)) throw UsageError("pair list skin must not be negative");
  material.validate();
  set_radii(radii);
}

void HertzSpheres::set_radii(const Eigen::VectorXd& radii) {
  if (radii.size() > 0 && (!(radii.minCoeff() > 0) || !radii.allFinite())) throw UsageError("radii must be positive");
  radii_ = radii;
  stale_ = true;
}

void HertzSpheres::ensure_list(const Eigen::VectorXd& x) {
  if (!stale_ && reference_.size() == x.size()) {
    // Rebuild once some sphere may have moved more than skin/2 (minimum image).
    const double limit2 = 0.25 * skin_ * skin_;
    bool moved = false;
    for (Eigen::Index k = 0; k < x.size() && !moved; k += 3)
      moved = minimum_image(&x[k], &reference_[k]).squaredNorm() > limit2;
    if (!moved) return;
  }
  build_list(x);
}

void HertzSpheres::build_list(const Eigen::VectorXd& x) {
  const int n = size();
  if (x.size() != 3L * n) throw UsageError("positions and radii disagree in number");
  const double r_max = n ? radii_.maxCoeff() : 0.0;
  const double half_box = box_.minCoeff() / 2;
  if (2 * r_max >= half_box)
    throw ComputationError("spheres of diameter " + std::to_string(2 * r_max) + " do not fit a periodic box of side " +
                           std::to_string(2 * half_box) +
                           " (one sphere would touch two images of another): use more particles");
  skin_ = skin_fraction_ * (n ? 2 * radii_.mean() : 0.0);
  skin_ = std::min(skin_, 0.999 * (half_box - 2 * r_max));  // one image per pair within the list's reach
  const double reach = 2 * r_max + skin_;
  std::vector<std::pair<int, int>> pairs;
  auto consider = [&](int i, int j, double r2) {
    const double s = radii_[i] + radii_[j] + skin_;
    if (r2 < s * s) pairs.emplace_back(std::min(i, j), std::max(i, j));
  };
  const mesh::VertexMatrix X = Eigen::Map<const mesh::VertexMatrix>(x.data(), n, 3);
  neighbours::Box box;
  box.lengths = box_;
  box.periodic = {true, true, true};
  if (n > 64 && reach <= half_box) {
    neighbours::CellGrid grid(box, reach);
    grid.build(X);
    grid.for_each_pair(X, [&](int i, int j, const Eigen::Vector3d&, double r2) { consider(i, j, r2); });
  } else {  // few spheres: all pairs
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) consider(i, j, minimum_image(&x[3 * i], &x[3 * j]).squaredNorm());
  }
  std::sort(pairs.begin(), pairs.end());
  const std::size_t m = pairs.size();
  first_.resize(m), second_.resize(m), reach_.resize(m), prefactor_.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    const auto [i, j] = pairs[k];
    first_[k] = i, second_[k] = j;
    reach_[k] = radii_[i] + radii_[j];
    prefactor_[k] = hertz_prefactor(material_, radii_[i], radii_[j]);
  }
  reference_ = x;
  stale_ = false;
  ++builds_;
}

void HertzSpheres::add_pair_forces(const double* x, std::size_t begin, std::size_t end, double* f) const {
  for (std::size_t k = begin; k < end; ++k) {
    const int i = first_[k], j = second_[k];
    const Eigen::Vector3d d = minimum_image(x + 3 * i, x + 3 * j);
    const double r2 = d.squaredNorm(), s = reach_[k];
    if (r2 >= s * s) continue;
    const double r = std::sqrt(r2), h = s - r;
    const Eigen::Vector3d fij = (prefactor_[k] * h * std::sqrt(h) / r) * d;
    for (int a = 0; a < 3; ++a) f[3 * i + a] += fij[a], f[3 * j + a] -= fij[a];
  }
}

void HertzSpheres::forces(const Eigen::VectorXd& x, Eigen::VectorXd& f) {
  ensure_list(x);
  const std::size_t m = first_.size();
  const Eigen::Index n3 = x.size();
  if (size() < kParallelForceSpheres) {
    f.setZero(n3);
    add_pair_forces(x.data(), 0, m, f.data());
    return;
  }
  f.resize(n3);
  chunk_forces_.resize(static_cast<std::size_t>(kForceChunks) * n3);
  double* buffers = chunk_forces_.data();
  for_each_chunk(kForceChunks, [&](int c) {
    double* buffer = buffers + c * n3;
    std::fill(buffer, buffer + n3, 0.0);
    add_pair_forces(x.data(), chunk_begin(m, kForceChunks, c), chunk_begin(m, kForceChunks, c + 1), buffer);
  });
  for_each_chunk(kForceChunks, [&](int c) {
    for (Eigen::Index k = chunk_begin(n3, kForceChunks, c); k < chunk_begin(n3, kForceChunks, c + 1); ++k) {
      double sum = buffers[k];
      for (int b = 1; b < kForceChunks; ++b) sum += buffers[b * n3 + k];
      f[k] = sum;
    }
  });
}

HertzState HertzSpheres::evaluate(const Eigen::VectorXd& x) {
  ensure_list(x);
  HertzState state;
  double virial = 0;
  for (std::size_t k = 0; k < first_.size(); ++k) {
    const int i = first_[k], j = second_[k];
    const Eigen::Vector3d d = minimum_image(&x[3 * i], &x[3 * j]);
    const double r = d.norm(), h = reach_[k] - r;
    if (!(h > 0)) continue;
    Contact c;
    c.i = i, c.j = j, c.branch = d, c.overlap = h, c.force = hertz_force(prefactor_[k], h);
    state.energy += hertz_energy(prefactor_[k], h);
    virial += r * c.force;
    state.contacts.push_back(c);
  }
  state.pressure = virial / (3 * box_.prod());
  return state;
}

}  // namespace cmp::spheres
