#pragma once
// Growth-driven jamming in a periodic square box (thesis 3.4.2): a colony starts from two
// randomly oriented cells and alternates growth steps with energy minimisation.
//
//   - to jamming: grow for dt (dt_0 = 0.002/gamma^0 at first), relax; when V/(kN) > 2 tol the
//     step is rejected (the colony goes back to its state before the step) and dt is halved;
//     when V/(kN) < tol the step is accepted and dt is reset to dt_0; the colony is jammed at
//     the first step with tol <= V/(kN) <= 2 tol (tol = eps_tol^2 = 1e-16);
//   - beyond jamming to phi_J + dphi: the same with the area fraction: a step that ends above
//     phi_J + dphi + margin is rejected (dt halved, no minimisation needed: growth sets phi),
//     one below phi_J + dphi - margin is accepted with dt reset to dt_0, and the protocol ends
//     inside the window (margin 0.5e-8);
//   - feedback beyond jamming: gamma_i = gamma_i^0 exp(-P_i/P_0) with P_i the bud pressure of
//     the relaxed state before the step (off below jamming, where it is ~exp(-1e-8/P_0) anyway,
//     so every P_0 shares the same jammed packing); with the adaptive step (on by default) dt
//     is scaled by max_i gamma_i^0 / max_i gamma_i, so the fastest cell grows as much per step
//     as without feedback.
#include "cells2d/cell.hpp"
#include "cells2d/contacts.hpp"
#include "cells2d/packing_analysis.hpp"
#include "cells2d/relax.hpp"
#include "core/random.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace cmp::cells2d {

struct GrowthParameters {
  double box = 15;              // side L [sigma]
  double dt0 = 0.002;           // growth step dt_0 [1/gamma^0]
  double rate_spread = 0.1;     // gamma_i^0 uniform in [1 - spread, 1 + spread]
  double P0 = std::numeric_limits<double>::infinity();  // feedback pressure [k]; inf = none
  bool adaptive_step = true;
  // After an accepted step, the thesis resets dt to dt_0 (reset_step = true). With false, dt
  // only doubles (up to dt_0): near jamming each accepted step then costs about one rejected
  // try instead of one per halving, for the same jamming criterion (a faster path, not the
  // thesis's; --double-step).
  bool reset_step = true;
  double phi_margin = 0.5e-8;   // window half-width around phi_J + dphi
  double min_dt = 1e-30;        // a step this small is a failure (ComputationError)
  long max_steps = 50'000'000;  // growth steps (accepted + rejected) before giving up
  std::string contact = "harmonic";
  RelaxParameters relax;

  // Throws cmp::UsageError naming the first bad field.
  void validate() const;
};

// One accepted step: what growth.csv holds.
struct StepRecord {
  long step = 0;            // accepted steps so far
  double time = 0;          // [1/gamma^0]
  double dt = 0;            // the step just taken [1/gamma^0]
  long iterations = 0;      // minimisation steps of this growth step (rejected tries included)
  int rejections = 0;       // tries rejected before this step was accepted
  const PackingAnalysis* packing = nullptr;
};

// Counters of a run.
struct GrowthCounters {
  long accepted = 0, rejected = 0;
  long iterations = 0;       // FIRE steps
  long evaluations = 0;      // force evaluations
};

class Colony {
 public:
  // Two randomly oriented cells near the box centre, 1.5 sigma apart along y: a bud-less one and
  // one of area 1.5 pi/4 (bud diameter sqrt(1/2)), each with its own gamma^0.
  Colony(const GrowthParameters& parameters, std::uint64_t seed);

  // Grows until jammed. observer (may be empty) sees every accepted step, the jammed one last.
  void grow_to_jamming(const std::function<void(const StepRecord&)>& observer = {});
  // Grows beyond jamming until phi in [phi_J + dphi - margin, phi_J + dphi + margin]; dphi must
  // not be below the current phi - phi_J. Needs grow_to_jamming first.
  void grow_beyond(double dphi, const std::function<void(const StepRecord&)>& observer = {});

  const std::vector<Cell>& cells() const { return cells_; }
  double time() const { return time_; }
  bool jammed() const { return jammed_; }
  double phi_jamming() const { return phi_jamming_; }
  double area_fraction() const { return cells2d::area_fraction(cells_, params_.box); }
  const GrowthCounters& counters() const { return counters_; }
  const GrowthParameters& parameters() const { return params_; }
  // Changes the feedback pressure (before growing beyond jamming): P0 = inf switches it off.
  void set_feedback(double P0) { params_.P0 = P0; }
  ContactEngine& engine() { return *engine_; }
  // The current packing, analysed.
  PackingAnalysis analyse() { return analyse_packing(cells_, *engine_); }

  Colony(const Colony& other);
  Colony& operator=(const Colony&) = delete;

 private:
  // The state a rejected try goes back to.
  struct Snapshot {
    std::vector<Cell> cells;
    Random rng;
    double time;
  };
  // gamma_i from the bud pressures (beyond jamming with finite P0), else gamma_i^0.
  void update_rates();
  // dt scaled by the adaptive rule.
  double step_size(double dt) const;
  void record(const std::function<void(const StepRecord&)>& observer, double dt, long iterations, int rejections);

  GrowthParameters params_;
  Random rng_;
  std::vector<Cell> cells_;
  std::unique_ptr<ContactEngine> engine_;
  double time_ = 0;
  bool jammed_ = false;
  double phi_jamming_ = 0;
  GrowthCounters counters_;
};

}  // namespace cmp::cells2d
