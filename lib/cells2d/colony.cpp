#include "cells2d/colony.hpp"

#include "cells2d/growth.hpp"
#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace cmp::cells2d {

void GrowthParameters::validate() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError(what);
  };
  require(std::isfinite(box) && box >= 2 * (1.0 + 1e-3 + 0.3), "box: must be at least 2.61 sigma (twice the lobe cutoff plus skin)");
  require(dt0 > 0 && std::isfinite(dt0), "dt0: must be positive");
  require(rate_spread >= 0 && rate_spread < 1, "rate spread: must lie in [0, 1)");
  require(P0 > 0, "P0: must be positive (inf for no feedback)");
  require(phi_margin > 0, "phi margin: must be positive");
  require(relax.tolerance > 0, "tolerance: must be positive");
  contact_law(contact);
}

Colony::Colony(const GrowthParameters& parameters, std::uint64_t seed) : params_(parameters), rng_(seed) {
  params_.validate();
  Domain domain;
  domain.lx = domain.ly = params_.box;
  engine_ = std::make_unique<ContactEngine>(domain, contact_law(params_.contact));
  const double c = 0.5 * params_.box;
  for (int k = 0; k < 2; ++k) {
    Cell cell;
    cell.x = c;
    cell.y = c + (k == 0 ? -0.75 : 0.75);
    cell.theta = rng_.uniform(0, 2 * std::numbers::pi);
    cell.bud = k == 0 ? 0.0 : std::sqrt(0.5);
    cell.rate0 = cell.rate = draw_rate(rng_, params_.rate_spread);
    cells_.push_back(cell);
  }
}

Colony::Colony(const Colony& o)
    : params_(o.params_), rng_(o.rng_), cells_(o.cells_),
      engine_(std::make_unique<ContactEngine>(o.engine_->domain(), o.engine_->law(), o.engine_->law_parameters())), time_(o.time_),
      jammed_(o.jammed_), phi_jamming_(o.phi_jamming_), counters_(o.counters_) {}

void Colony::update_rates() {
  if (!jammed_ || !std::isfinite(params_.P0)) {
    for (Cell& c : cells_) c.rate = c.rate0;
    return;
  }
  const std::vector<double> P = bud_pressures(cells_, *engine_);
  for (std::size_t i = 0; i < cells_.size(); ++i) cells_[i].rate = cells_[i].rate0 * std::exp(-P[i] / params_.P0);
}

double Colony::step_size(double dt) const {
  if (!params_.adaptive_step) return dt;
  double fastest0 = 0, fastest = 0;
  for (const Cell& c : cells_) fastest0 = std::max(fastest0, c.rate0), fastest = std::max(fastest, c.rate);
  return fastest > 0 ? dt * fastest0 / fastest : dt;
}

void Colony::record(const std::function<void(const StepRecord&)>& observer, double dt, long iterations,
                    int rejections) {
  if (!observer) return;
  const PackingAnalysis packing = analyse();
  StepRecord r;
  r.step = counters_.accepted;
  r.time = time_;
  r.dt = dt;
  r.iterations = iterations;
  r.rejections = rejections;
  r.packing = &packing;
  observer(r);
}

void Colony::grow_to_jamming(const std::function<void(const StepRecord&)>& observer) {
  const double tol = params_.relax.tolerance;
  double dt = params_.dt0;
  long iterations = 0;
  int rejections = 0;
  update_rates();
  while (!jammed_) {
    if (counters_.accepted + counters_.rejected >= params_.max_steps)
      throw ComputationError("jamming: no jammed packing after " + std::to_string(params_.max_steps) + " growth steps");
    const Snapshot before{cells_, rng_, time_};
    const double h = step_size(dt);
    grow_cells(cells_, h, rng_, params_.rate_spread);
    time_ += h;
    const RelaxResult r = relax_or_fail(cells_, *engine_, params_.relax, "growth");
    counters_.iterations += r.iterations, counters_.evaluations += r.evaluations;
    iterations += r.iterations;
    const double per_cell = r.energy / static_cast<double>(cells_.size());
    if (per_cell > 2 * tol) {
      cells_ = before.cells, rng_ = before.rng, time_ = before.time;
      ++counters_.rejected, ++rejections;
      dt *= 0.5;
      if (dt < params_.min_dt)
        throw ComputationError("jamming: the growth step fell below " + std::to_string(params_.min_dt) +
                               " without reaching tol <= V/(kN) <= 2 tol");
      continue;
    }
    ++counters_.accepted;
    if (per_cell >= tol) {
      jammed_ = true;
      phi_jamming_ = area_fraction();
    } else {
      dt = params_.reset_step ? params_.dt0 : std::min(2 * dt, params_.dt0);
    }
    record(observer, h, iterations, rejections);
    iterations = 0, rejections = 0;
  }
}

void Colony::grow_beyond(double dphi, const std::function<void(const StepRecord&)>& observer) {
  if (!jammed_) throw UsageError("grow_beyond: the colony is not jammed yet");
  const double target = phi_jamming_ + dphi, margin = params_.phi_margin;
  if (area_fraction() > target + margin)
    throw UsageError("grow_beyond: the colony is already beyond phi_J + dphi");
  double dt = params_.dt0;
  long iterations = 0;
  int rejections = 0;
  while (area_fraction() < target - margin) {
    if (counters_.accepted + counters_.rejected >= params_.max_steps)
      throw ComputationError("growth beyond jamming: phi_J + dphi not reached after " +
                             std::to_string(params_.max_steps) + " growth steps");
    update_rates();
    const Snapshot before{cells_, rng_, time_};
    const double h = step_size(dt);
    grow_cells(cells_, h, rng_, params_.rate_spread);
    time_ += h;
    if (area_fraction() > target + margin) {  // rejected on phi alone: no minimisation needed
      cells_ = before.cells, rng_ = before.rng, time_ = before.time;
      ++counters_.rejected, ++rejections;
      dt *= 0.5;
      if (dt < params_.min_dt)
        throw ComputationError("growth beyond jamming: the growth step fell below the smallest allowed");
      continue;
    }
    const RelaxResult r = relax_or_fail(cells_, *engine_, params_.relax, "growth");
    counters_.iterations += r.iterations, counters_.evaluations += r.evaluations;
    iterations += r.iterations;
    ++counters_.accepted;
    dt = params_.reset_step ? params_.dt0 : std::min(2 * dt, params_.dt0);
    update_rates();
    record(observer, h, iterations, rejections);
    iterations = 0, rejections = 0;
  }
}

}  // namespace cmp::cells2d
