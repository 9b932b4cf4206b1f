#pragma once
// The CSV tables of jam2d (docs/formats.md): growth.csv (one row per accepted growth step),
// the moduli table and the sweep table (one row per packing), with the units in `# units=`.
#include "cells2d/colony.hpp"
#include "cells2d/moduli.hpp"

#include <string>
#include <vector>

namespace cmp::cells2d {

inline const char* kUnits = "lengths sigma (mother diameter), time 1/gamma0, pressure and moduli k, energy k sigma^2";

// growth.csv: step, time, dt, cells, phi, pressure, Z, f_u, rattlers, mean_rate,
// energy_per_cell, rejected (tries rejected before this step), fire_iterations.
std::vector<std::string> growth_columns();
std::vector<std::string> growth_row(const StepRecord& r);

// One row per packing: cells, box, phi, pressure, pressure_xx, pressure_yy, pressure_xy, B,
// G, Z, Z_iso, f_u, rattlers, contacts, energy_per_cell, relaxed (1 when the moduli's three
// relaxations reached force balance, 0 when one ran out of iterations: B and G less exact).
std::vector<std::string> packing_columns();
std::vector<std::string> packing_row(const Moduli& m, double box);

// Inclusive numeric list FIRST:LAST:STEP or a comma list ("0:0.1:0.01", "0,0.02"); every
// value >= 0, sorted ascending, duplicates removed. Throws cmp::UsageError naming the text.
std::vector<double> parse_dphi_list(const std::string& text);
// Comma list of feedback pressures, "inf" for none ("inf,0.005,0.001"); every value > 0.
// Throws cmp::UsageError.
std::vector<double> parse_feedback_list(const std::string& text);
// "inf" or a positive number. Throws cmp::UsageError.
double parse_feedback(const std::string& text);

// Everything `sweep` does for one seed: jam once, then for every P0 grow (a copy of the
// jammed colony) through the dphi list in order, measuring the moduli of each packing.
// Rows: seed, P0, dphi, phi_J, then packing_columns(), then mean_rate (Gamma [gamma0]),
// accepted_steps, fire_iterations.
std::vector<std::string> sweep_columns();
std::vector<std::vector<std::string>> sweep_seed(std::uint64_t seed, const GrowthParameters& parameters,
                                                 const std::vector<double>& dphis, const std::vector<double>& P0s);

}  // namespace cmp::cells2d
