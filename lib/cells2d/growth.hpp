#pragma once
// Growth and division of budding cells (thesis S3.1, Fig. S3.1): the area of cell i grows as
// da/dt = gamma_i a by bud expansion (the mother keeps diameter sigma, the centre of mass stays
// put); when the bud reaches sigma the cell divides into two bud-less cells at the old lobe
// centres with random orientations and fresh gamma^0 draws. Time in units of 1/gamma^0.
#include "cells2d/cell.hpp"
#include "core/random.hpp"

#include <vector>

namespace cmp::cells2d {

// gamma_i^0 drawn uniformly from [1 - spread, 1 + spread] gamma^0 (the thesis's "uniform
// distribution of width 20 %": spread = 0.1).
inline double draw_rate(Random& rng, double spread) { return rng.uniform(1 - spread, 1 + spread); }

// Grows every cell for a time dt [1/gamma^0] at its current rate: a -> a exp(gamma_i dt)
// (exact for a constant rate). A cell whose area reaches pi sigma^2 / 2 divides: the parent's
// slot holds the daughter at the old mother centre, the other daughter is appended; each gets
// half of the area grown beyond division as a small bud (so the total area is exactly what
// growth made), an orientation uniform in [0, 2 pi) and a new gamma^0. Returns the number of
// divisions.
int grow_cells(std::vector<Cell>& cells, double dt, Random& rng, double rate_spread);

// The two cells a dividing cell becomes (exposed for tests): area = its area, >= pi/2. With
// keep_orientation both keep the parent's orientation (the chamber of Chapter 2) instead of
// drawing new ones (the periodic box of Chapter 3).
void divide_cell(const Cell& parent, double area, Random& rng, double rate_spread, Cell& first, Cell& second,
                 bool keep_orientation = false);

}  // namespace cmp::cells2d
