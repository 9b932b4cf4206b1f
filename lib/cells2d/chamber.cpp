#include "cells2d/chamber.hpp"

#include "cells2d/growth.hpp"
#include "core/errors.hpp"
#include "io/checkpoint_file.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <istream>
#include <numbers>
#include <ostream>

namespace cmp::cells2d {

std::vector<std::pair<std::string, std::string>> ChamberParameters::problems() const {
  auto out = geometry.problems();
  const auto require = [&](bool ok, const char* option, const std::string& what) {
    if (!ok) out.emplace_back(option, what);
  };
  const auto known = [&](const char* option, const std::function<void()>& f) {
    try {
      f();
    } catch (const UsageError& e) {
      out.emplace_back(option, e.what());
    }
  };
  known("--contact", [&] { contact_law(contact); });
  known("--integrator", [&] { integrator_style(integrator); });
  require(std::isfinite(attraction) && attraction >= 0 && attraction < 0.5, "--attraction", "must lie in [0, 0.5) sigma");
  require(std::isfinite(mobility) && mobility > 0, "--mobility", "must be positive");
  require(std::isfinite(dt) && dt >= 0, "--dt", "must be positive (0: chosen from --mobility and --integrator)");
  const auto* style = [&]() -> const IntegratorStyle* {
    for (const auto& s : integrator_styles())
      if (integrator == s.name) return &s;
    return nullptr;
  }();
  if (style && std::isfinite(mobility) && mobility > 0 && std::isfinite(dt))
    require(!(time_step() * mobility > style->stability_limit), "--dt",
            fmt::format("must be at most {} / mobility = {} for {}: even one contact is unstable beyond",
                        style->stability_limit, io::format_number(style->stability_limit / mobility), integrator));
  require(rate_spread >= 0 && rate_spread < 1, "--rate-spread", "must lie in [0, 1)");
  require(P0 > 0, "--P0", "must be positive ('inf' for no feedback)");
  require(feedback_pressure == "cell" || feedback_pressure == "bud", "--feedback-pressure", "must be 'cell' or 'bud'");
  require(std::isfinite(feedback_interval) && feedback_interval > 0, "--feedback-interval", "must be positive");
  return out;
}

double ChamberParameters::time_step() const {
  return dt > 0 ? dt : integrator_style(integrator).stability_limit / (20 * mobility);
}

void ChamberParameters::validate() const {
  const auto p = problems();
  if (!p.empty()) throw UsageError(p.front().first + ": " + p.front().second);
}

ChamberRun::ChamberRun(const ChamberParameters& parameters, std::uint64_t seed)
    : ChamberRun(parameters, seed, {}) {}

ChamberRun::ChamberRun(const ChamberParameters& parameters, std::uint64_t seed, std::vector<Cell> cells)
    : params_(parameters), dt_(parameters.time_step()), rng_(seed), cells_(std::move(cells)) {
  params_.validate();
  engine_ = std::make_unique<ContactEngine>(params_.geometry.domain(), contact_law(params_.contact),
                                            LawParameters{params_.attraction});
  walls_ = std::make_unique<ChamberWalls>(params_.geometry, contact_law(params_.contact));
  integrator_ = integrator_style(params_.integrator).make();
  if (cells_.empty()) {
    Cell c;
    c.x = 0.5 * params_.geometry.width;
    c.y = 0.5 * params_.geometry.height;
    c.theta = rng_.uniform(0, 2 * std::numbers::pi);
    c.rate0 = c.rate = draw_rate(rng_, params_.rate_spread);
    cells_.push_back(c);
  }
  for (const Cell& c : cells_)
    if (!params_.geometry.contains(c.x, c.y))
      throw UsageError(fmt::format("a cell at ({}, {}) lies outside the chamber", c.x, c.y));
  fresh_.assign(3 * cells_.size(), 1);
  update_rates();
}

double ChamberRun::forces(std::vector<double>& force) {
  force.resize(3 * cells_.size());
  const double e = engine_->evaluate(cells_, force.data());
  return e + walls_->add_forces(cells_, force.data());
}

void ChamberRun::velocity(const std::vector<double>& state, std::vector<double>& v) {
  const std::size_t n = scratch_.size();
  for (std::size_t i = 0; i < n; ++i) {
    scratch_[i].x = state[3 * i], scratch_[i].y = state[3 * i + 1], scratch_[i].theta = state[3 * i + 2];
  }
  force_.resize(3 * n);
  engine_->evaluate(scratch_, force_.data());
  walls_->add_forces(*engine_, force_.data());
  const double mu = params_.mobility;
  for (std::size_t i = 0; i < n; ++i) {
    v[3 * i] = mu * force_[3 * i];
    v[3 * i + 1] = mu * force_[3 * i + 1];
    v[3 * i + 2] = mu * force_[3 * i + 2] / inertia_per_mass(scratch_[i].bud);
  }
}

void ChamberRun::step() {
  // Growth at constant rates over the step: a -> a exp(gamma_i dt); a cell reaching pi/2
  // divides in place, the second daughter appended, both keeping the orientation.
  if (params_.grow) {
    const std::size_t n = cells_.size();
    for (std::size_t i = 0; i < n; ++i) {
      Cell& c = cells_[i];
      const double b2 = (1 + c.bud * c.bud) * growth_factor_[i] - 1;
      if (b2 < 1) {
        c.bud = b2 > 0 ? std::sqrt(b2) : 0.0;
        continue;
      }
      Cell first, second;
      divide_cell(c, 0.25 * std::numbers::pi * (1 + b2), rng_, params_.rate_spread, first, second, true);
      cells_[i] = first;
      cells_.push_back(second);
      for (int k = 0; k < 3; ++k) fresh_[3 * i + k] = 1;
      fresh_.insert(fresh_.end(), 3, 1);
      ++divisions_;
    }
    if (cells_.size() != n) {
      engine_->renumbered();  // a daughter took its parent's slot
      // New cells grow at their own rates (feedback reaches them at the next update).
      growth_factor_.resize(cells_.size());
      for (std::size_t i = 0; i < cells_.size(); ++i) growth_factor_[i] = std::exp(cells_[i].rate * dt_);
    }
  }
  // Motion.
  const std::size_t n = cells_.size();
  state_.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    state_[3 * i] = cells_[i].x, state_[3 * i + 1] = cells_[i].y, state_[3 * i + 2] = cells_[i].theta;
  }
  scratch_ = cells_;
  integrator_->step(state_, dt_, [this](const std::vector<double>& y, std::vector<double>& v) { velocity(y, v); },
                    fresh_);
  for (std::size_t i = 0; i < n; ++i) {
    cells_[i].x = state_[3 * i], cells_[i].y = state_[3 * i + 1], cells_[i].theta = state_[3 * i + 2];
  }
  ++steps_;
  // Removal past the channel's end. A cell whose centre of mass lies beyond a wall by more than
  // a mother's diameter (an overlap of 1.5 sigma) has blown through it: the step is unstable.
  std::vector<char> keep(3 * n, 1);
  bool removed = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Cell& c = cells_[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !params_.geometry.contains(c.x, c.y, 1.0))
      throw ComputationError(fmt::format(
          "at t = {}/gamma0 a cell left the chamber through a wall (at x = {}, y = {}): the time step {} is too large "
          "for the mobility {} (try a smaller --dt)",
          time(), c.x, c.y, dt_, params_.mobility));
    if (c.y < -params_.geometry.channel) {
      for (int k = 0; k < 3; ++k) keep[3 * i + k] = 0;
      removed = true;
    }
  }
  if (removed) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!keep[3 * i]) {
        ++left_;
        continue;
      }
      cells_[out] = cells_[i];
      growth_factor_[out] = growth_factor_[i];
      for (int k = 0; k < 3; ++k) fresh_[3 * out + k] = fresh_[3 * i + k];
      ++out;
    }
    cells_.resize(out), growth_factor_.resize(out), fresh_.resize(3 * out);
    integrator_->compact(keep);
    engine_->renumbered();
  }
  if (steps_ >= next_rate_update_) update_rates();
}

void ChamberRun::advance_to(double t) {
  while (time() < t - 0.5 * dt_) step();
}

std::vector<double> ChamberRun::cell_pressures(bool bud_only) {
  const std::size_t n = cells_.size();
  std::vector<double> force(n, 0.0);
  const auto add = [&](int lobe, double f) {
    if (!bud_only || (lobe & 1)) force[static_cast<std::size_t>(lobe >> 1)] += std::abs(f);
  };
  engine_->for_each_contact(cells_, [&](const Contact& c) {
    if (c.overlap <= 0) return;
    add(c.a, c.force), add(c.b, c.force);
  });
  walls_->for_each_contact(cells_, [&](const WallContact& w) { add(w.lobe, w.force); });
  for (std::size_t i = 0; i < n; ++i) {
    const double perimeter = std::numbers::pi * (bud_only ? cells_[i].bud : 1 + cells_[i].bud);
    force[i] = perimeter > 0 ? force[i] / perimeter : 0.0;
  }
  return force;
}

void ChamberRun::update_rates() {
  const std::size_t n = cells_.size();
  if (std::isfinite(params_.P0)) {
    const std::vector<double> P = cell_pressures(params_.feedback_pressure == "bud");
    for (std::size_t i = 0; i < n; ++i) cells_[i].rate = cells_[i].rate0 * std::exp(-P[i] / params_.P0);
  } else {
    for (Cell& c : cells_) c.rate = c.rate0;
  }
  growth_factor_.resize(n);
  for (std::size_t i = 0; i < n; ++i) growth_factor_[i] = std::exp(cells_[i].rate * dt_);
  next_rate_update_ = steps_ + std::max(1L, std::lround(params_.feedback_interval / dt_));
}

void ChamberRun::save(std::ostream& out) const {
  io::put(out, steps_), io::put(out, left_), io::put(out, divisions_), io::put(out, next_rate_update_);
  io::put(out, rng_);
  io::put(out, cells_);
  io::put(out, growth_factor_);
  io::put(out, fresh_);
  io::put(out, integrator_->history());
  io::put(out, integrator_->evaluations());
}

void ChamberRun::load(io::CheckpointReader& in) {
  constexpr std::uint64_t kMax = 100'000'000;
  steps_ = in.get<long>();  // one statement each: the reads must happen in this order
  left_ = in.get<long>();
  divisions_ = in.get<long>();
  next_rate_update_ = in.get<long>();
  in.get_into(rng_);
  cells_ = in.get_vector<Cell>(kMax);
  growth_factor_ = in.get_vector<double>(kMax);
  fresh_ = in.get_vector<char>(3 * kMax);
  std::vector<double> history = in.get_vector<double>(4 * kMax);
  const long evaluations = in.get<long>();
  integrator_->set_history(std::move(history), evaluations);
  if (growth_factor_.size() != cells_.size() || fresh_.size() != 3 * cells_.size())
    throw InputError(in.path(), 0, "truncated or damaged checkpoint");
}

ChamberSample ChamberRun::sample() {
  ChamberSample s;
  s.time = time();
  s.steps = steps_;
  s.cells = static_cast<int>(cells_.size());
  s.left = left_;
  std::vector<char> inside(cells_.size());
  double area = 0, rate_area = 0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    inside[i] = params_.geometry.in_chamber(cells_[i].y);
    if (!inside[i]) continue;
    ++s.chamber_cells;
    area += cell_area(cells_[i].bud), rate_area += cell_area(cells_[i].bud) * cells_[i].rate;
  }
  s.growth_rate = area > 0 ? rate_area / area : 0.0;
  double virial = 0;
  engine_->for_each_contact(cells_, [&](const Contact& c) {
    s.energy += engine_->pair_energy(c.overlap);
    if (inside[static_cast<std::size_t>(c.a >> 1)] && inside[static_cast<std::size_t>(c.b >> 1)])
      virial += c.force * c.distance;
  });
  s.pressure_virial = virial / (2 * params_.geometry.area());
  double wall_force = 0;
  walls_->for_each_contact(cells_, [&](const WallContact& w) {
    if (w.chamber) wall_force += w.force;
  });
  s.energy += walls_->energy(cells_);
  s.pressure_walls = wall_force / params_.geometry.wall_length();
  const std::vector<double> P = cell_pressures(false);
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < cells_.size(); ++i)
    if (inside[i]) sum += P[i], sum2 += P[i] * P[i];
  if (s.chamber_cells > 0 && sum > 0) {
    const double mean = sum / s.chamber_cells, mean2 = sum2 / s.chamber_cells;
    s.cell_pressure_cv = std::sqrt(std::max(0.0, mean2 / (mean * mean) - 1));
  }
  std::vector<double> f;
  forces(f);
  for (std::size_t i = 0; i < cells_.size(); ++i) s.max_force = std::max(s.max_force, std::hypot(f[3 * i], f[3 * i + 1]));
  return s;
}

LobeLoads ChamberRun::lobe_loads() {
  LobeLoads l;
  l.force.assign(2 * cells_.size(), 0.0);
  l.contacts.assign(2 * cells_.size(), 0);
  engine_->for_each_contact(cells_, [&](const Contact& c) {
    if (c.overlap <= 0) return;
    for (int lobe : {c.a, c.b}) l.force[static_cast<std::size_t>(lobe)] += std::abs(c.force), ++l.contacts[static_cast<std::size_t>(lobe)];
  });
  walls_->for_each_contact(cells_, [&](const WallContact& w) {
    l.force[static_cast<std::size_t>(w.lobe)] += w.force, ++l.contacts[static_cast<std::size_t>(w.lobe)];
  });
  return l;
}

}  // namespace cmp::cells2d
