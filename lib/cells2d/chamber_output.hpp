#pragma once
// What `jam2d chamber` writes (docs/jam2d.md): the time series, one CSV row per sample, and
// extended-XYZ frames of the chamber, one row per lobe with the lobe's summed contact force so
// that OVITO can colour the force chains. The frame's Lattice spans the chamber and channel
// (width by height + channel, Origin at the channel's end), pbc="F F F".
#include "cells2d/chamber.hpp"
#include "io/xyz_frame.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cmp::cells2d {

// time, steps, cells, chamber_cells, left, pressure_walls, pressure_virial, growth_rate, c_P,
// energy, max_force.
std::vector<std::string> chamber_columns();
std::vector<std::string> chamber_row(const ChamberSample& s);

// The run's parameters as key-value pairs (CSV meta lines and the frames' comment line).
std::vector<std::pair<std::string, std::string>> chamber_info(const ChamberParameters& p, std::uint64_t seed);

// species X, pos, radius, cell, lobe, orientation, force (sum |F| on the lobe [k sigma]),
// pressure (force over the lobe's perimeter [k]), contacts.
io::XyzFrame chamber_frame(ChamberRun& run, const std::vector<std::pair<std::string, std::string>>& info);

}  // namespace cmp::cells2d
