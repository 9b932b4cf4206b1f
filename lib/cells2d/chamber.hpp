#pragma once
// Self-driven jamming of budding cells in a chamber with an outlet (thesis Chapter 2, 2.5): the
// cells of lib/cells2d grow at gamma_i (S2.10), divide keeping their mother's orientation, move
// by over-damped dynamics r' = mu F, theta' = (m/I) mu T (S2.11-S2.12) under the contact law and
// the walls (chamber_walls.hpp), and are removed once their centre of mass has left through the
// channel. Units: sigma (mother diameter), k (contact stiffness), time 1/gamma^0 (the mean
// growth rate without feedback); the mobility is mu k / gamma^0, the thesis's mu/(gamma sqrt(mk))
// read with m = 1 (digest: the printed unit is not dimensionless; what sets the dynamics is
// the ratio of the relaxation rate mu k to the growth rate).
//
// Feedback (optional): gamma_i = gamma_i^0 exp(-P_i / P0), P_i the cell's pressure (sum of the
// contact and wall force magnitudes on the cell over its perimeter pi (sigma + sigma_bud)) or,
// as in Chapter 3, its bud's; the rates are refreshed every feedback interval.
#include "cells2d/cell.hpp"
#include "cells2d/chamber_walls.hpp"
#include "cells2d/contacts.hpp"
#include "cells2d/overdamped.hpp"
#include "core/random.hpp"

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace cmp::io {
class CheckpointReader;
}

namespace cmp::cells2d {

struct ChamberParameters {
  ChamberGeometry geometry;
  std::string contact = "harmonic";
  double attraction = 0;            // the sticky law's Delta [sigma]
  double mobility = 8e4;            // mu k / gamma^0 (thesis: 8e4 without feedback, 2e3 with)
  // Time step [1/gamma^0]; 0: the integrator's stability limit / (20 mu k), a margin of two
  // over the stiffest mode (about 10 mu k): 0.1/mobility for euler, 0.027/mobility for gear3.
  double dt = 0;
  std::string integrator = "gear3";
  double rate_spread = 0.1;         // gamma_i^0 uniform in [1 - spread, 1 + spread]
  double P0 = std::numeric_limits<double>::infinity();  // feedback pressure [k]; inf: none
  std::string feedback_pressure = "cell";  // "cell" or "bud"
  double feedback_interval = 1e-3;  // [1/gamma^0] between rate updates
  bool grow = true;                 // false: the cells only move (relaxation tests)

  // Every problem as (option, message), the geometry's included; empty when sound.
  std::vector<std::pair<std::string, std::string>> problems() const;
  // Throws cmp::UsageError naming the first problem's option.
  void validate() const;
  double time_step() const;
};

// What a row of the time series holds.
struct ChamberSample {
  double time = 0;           // [1/gamma^0]
  long steps = 0;
  int cells = 0;             // alive (chamber and channel)
  int chamber_cells = 0;     // centre of mass inside the chamber (y >= 0)
  long left = 0;             // removed through the channel so far
  double pressure_walls = 0;   // normal force on the chamber's walls per unit length [k]
  double pressure_virial = 0;  // (1/2A) sum over pairs in the chamber of d . f [k]
  double growth_rate = 0;    // area-weighted mean gamma_i of the chamber's cells [gamma^0]
  double cell_pressure_cv = 0;  // c_P = sqrt(<P^2>/<P>^2 - 1) over the chamber's cells (0 if all P = 0)
  double energy = 0;         // contacts + walls [k sigma^2]
  double max_force = 0;      // largest |F| on a cell [k sigma]
};

// Per-lobe numbers for pictures (OVITO's force chains).
struct LobeLoads {
  std::vector<double> force;   // sum of |F| of the lobe's contacts and wall contacts [k sigma]
  std::vector<int> contacts;   // touching lobes and walls
};

class ChamberRun {
 public:
  // One bud-less cell of random orientation at the chamber's centre (the experiment traps one
  // cell), unless cells are given.
  ChamberRun(const ChamberParameters& parameters, std::uint64_t seed);
  ChamberRun(const ChamberParameters& parameters, std::uint64_t seed, std::vector<Cell> cells);

  // Steps until time() reaches t (to within a step).
  void advance_to(double t);
  // One step: growth and division, motion, removal.
  void step();

  ChamberSample sample();
  LobeLoads lobe_loads();
  // Forces and torques on every cell (3 per cell) [k sigma, k sigma^2]; returns the energy.
  double forces(std::vector<double>& force);

  const std::vector<Cell>& cells() const { return cells_; }
  double time() const { return static_cast<double>(steps_) * dt_; }
  long steps() const { return steps_; }
  long left() const { return left_; }
  long divisions() const { return divisions_; }
  const ChamberParameters& parameters() const { return params_; }
  long evaluations() const { return integrator_->evaluations(); }

  // The whole state, bit for bit (io/checkpoint_file.hpp's raw values): a run restored from it
  // continues exactly as the saved one would have. The parameters are the caller's to check.
  void save(std::ostream& out) const;
  void load(io::CheckpointReader& in);
  long list_builds() const { return engine_->list_builds(); }

 private:
  void update_rates();
  std::vector<double> cell_pressures(bool bud_only);
  void velocity(const std::vector<double>& state, std::vector<double>& v);

  ChamberParameters params_;
  double dt_;
  Random rng_;
  std::vector<Cell> cells_;
  std::vector<double> growth_factor_;  // exp(gamma_i dt) per cell
  std::unique_ptr<ContactEngine> engine_;
  std::unique_ptr<ChamberWalls> walls_;
  std::unique_ptr<OverdampedIntegrator> integrator_;
  std::vector<double> state_, force_;
  std::vector<Cell> scratch_;
  std::vector<char> fresh_;
  long steps_ = 0, left_ = 0, divisions_ = 0;
  long next_rate_update_ = 0;  // step of the next feedback update
};

}  // namespace cmp::cells2d
