#include "cells2d/growth.hpp"

#include <cmath>
#include <numbers>

namespace cmp::cells2d {

void divide_cell(const Cell& parent, double area, Random& rng, double rate_spread, Cell& first, Cell& second,
                 bool keep_orientation) {
  // At division the bud equals the mother: the lobe centres are the centre of mass +- e/2.
  const double ex = std::cos(parent.theta), ey = std::sin(parent.theta);
  const double bud = bud_for_area(0.5 * area);  // each daughter: half of the area
  Cell* daughters[2] = {&first, &second};
  for (int k = 0; k < 2; ++k) {
    Cell& d = *daughters[k];
    const double s = k == 0 ? 0.5 : -0.5;
    d.theta = keep_orientation ? parent.theta : rng.uniform(0, 2 * std::numbers::pi);
    d.bud = bud;
    d.rate0 = d.rate = draw_rate(rng, rate_spread);
    // The daughter's mother sits where the parent's lobe was: its centre of mass is shifted
    // back by the (small) mother offset of its bud.
    const double m = mother_offset(bud);
    d.x = parent.x + s * ex - m * std::cos(d.theta);
    d.y = parent.y + s * ey - m * std::sin(d.theta);
  }
}

int grow_cells(std::vector<Cell>& cells, double dt, Random& rng, double rate_spread) {
  const std::size_t n = cells.size();
  int divisions = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double area = cell_area(cells[i].bud) * std::exp(cells[i].rate * dt);
    if (area < kDivisionArea) {
      cells[i].bud = bud_for_area(area);
      continue;
    }
    Cell first, second;
    divide_cell(cells[i], area, rng, rate_spread, first, second);
    cells[i] = first;
    cells.push_back(second);
    ++divisions;
  }
  return divisions;
}

}  // namespace cmp::cells2d
