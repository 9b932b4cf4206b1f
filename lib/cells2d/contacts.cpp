#include "cells2d/contacts.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace cmp::cells2d {

namespace {
// The largest lobe-lobe reach (two mothers) plus room for a Lees-Edwards strain of ~1e-3; an
// attractive law adds its range.
constexpr double kCutoff = 1.0 + 1e-3;
constexpr std::size_t kSerialBuildCells = 20000;

neighbours::Box planar_box(const Domain& d) {
  if (!(d.lx > 0) || !(d.ly > 0)) throw UsageError("cells2d: the box must have positive sides");
  return neighbours::make_planar_box(Eigen::Vector2d::Zero(), Eigen::Vector2d(d.lx, d.ly), d.periodic, d.periodic);
}
}  // namespace

ContactEngine::ContactEngine(const Domain& domain, const ContactLawStyle& law, const LawParameters& parameters,
                             double skin)
    : domain_(domain), law_(&law), parameters_(parameters), range_(law.range(parameters)), skin_(skin),
      list_(planar_box(domain), kCutoff + range_, skin) {
  if (!(range_ >= 0) || !std::isfinite(range_)) throw UsageError("cells2d: a contact law's range must be finite and >= 0");
}

void ContactEngine::place_lobes(const std::vector<Cell>& cells) {
  const std::size_t n = cells.size();
  if (static_cast<std::size_t>(lobes_.rows()) != 2 * n) {
    lobes_.resize(static_cast<Eigen::Index>(2 * n), 3);
    lobes_.col(2).setZero();
    radius_.resize(2 * n), offset_x_.resize(2 * n), offset_y_.resize(2 * n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Cell& c = cells[i];
    const double ex = std::cos(c.theta), ey = std::sin(c.theta);
    const double m = mother_offset(c.bud), b = -bud_offset(c.bud);
    offset_x_[2 * i] = m * ex, offset_y_[2 * i] = m * ey;
    offset_x_[2 * i + 1] = b * ex, offset_y_[2 * i + 1] = b * ey;
    radius_[2 * i] = 0.5, radius_[2 * i + 1] = 0.5 * c.bud;
    for (int k = 0; k < 2; ++k) {
      const std::size_t l = 2 * i + k;
      lobes_(static_cast<Eigen::Index>(l), 0) = c.x + offset_x_[l];
      lobes_(static_cast<Eigen::Index>(l), 1) = c.y + offset_y_[l];
    }
  }
  // Rebuild when a lobe has moved or grown by a quarter of the skin since the pairs were built.
  bool stale = pairs_stale_ || built_at_.rows() != lobes_.rows();
  const double quarter = 0.25 * skin_, quarter2 = quarter * quarter;
  for (std::size_t l = 0; !stale && l < 2 * n; ++l) {
    const auto r = static_cast<Eigen::Index>(l);
    const double dx = lobes_(r, 0) - built_at_(r, 0), dy = lobes_(r, 1) - built_at_(r, 1);
    stale = dx * dx + dy * dy > quarter2 || radius_[l] - built_radius_[l] > quarter;
  }
  if (!stale) return;
  // The list's build is parallel; for colonies of this size a team's wake-ups and barriers
  // cost more than the build (measured: half the run time on a busy machine), so it runs on
  // one thread.
  const int threads = omp_get_max_threads();
  if (n < kSerialBuildCells && threads > 1) omp_set_num_threads(1);
  list_.build(lobes_);
  if (n < kSerialBuildCells && threads > 1) omp_set_num_threads(threads);
  build_pairs();
}

void ContactEngine::build_pairs() {
  const int lobes = static_cast<int>(radius_.size());
  pair_start_.assign(static_cast<std::size_t>(lobes) + 1, 0);
  pair_j_.clear();
  // A pair can touch before the next rebuild if it is within reach plus the skin now (each lobe
  // moves or grows by at most a quarter skin), plus the list's own margin for a strain change.
  const double margin = skin_ + (kCutoff - 1.0);
  for (int i = 0; i < lobes; ++i) {
    pair_start_[static_cast<std::size_t>(i)] = static_cast<int>(pair_j_.size());
    const Eigen::Vector2d pi(lobes_(i, 0), lobes_(i, 1));
    for (int j : list_.neighbours_of(i)) {
      if (j <= i || (j >> 1) == (i >> 1)) continue;
      const Eigen::Vector2d d = domain_.separation(pi - Eigen::Vector2d(lobes_(j, 0), lobes_(j, 1)));
      const double reach = radius_[static_cast<std::size_t>(i)] + radius_[static_cast<std::size_t>(j)] + range_ + margin;
      if (d.squaredNorm() < reach * reach) pair_j_.push_back(j);
    }
  }
  pair_start_[static_cast<std::size_t>(lobes)] = static_cast<int>(pair_j_.size());
  built_at_ = lobes_;
  built_radius_ = radius_;
  pairs_stale_ = false;
}

double ContactEngine::evaluate(const std::vector<Cell>& cells, double* force) {
  place_lobes(cells);
  return law_->kernel(*this, cells, force);
}

double ContactEngine::energy(const std::vector<Cell>& cells) {
  double e = 0;
  for_each_contact(cells, [&](const Contact& c) { e += pair_energy(c.overlap); });
  return e;
}

}  // namespace cmp::cells2d
