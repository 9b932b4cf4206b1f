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
    : domain_(domain), law_(&law), parameters_(parameters), range_(law.range(parameters)),
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
  // The list's build is parallel; for colonies of this size a team's wake-ups and barriers
  // cost more than the build (measured: half the run time on a busy machine), so it runs on
  // one thread.
  if (list_.needs_rebuild(lobes_)) {
    const int threads = omp_get_max_threads();
    if (n < kSerialBuildCells && threads > 1) omp_set_num_threads(1);
    list_.build(lobes_);
    if (n < kSerialBuildCells && threads > 1) omp_set_num_threads(threads);
  }
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
