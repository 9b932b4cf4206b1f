#include "cells2d/cell.hpp"

namespace cmp::cells2d {

double total_area(const std::vector<Cell>& cells) {
  double a = 0;
  for (const Cell& c : cells) a += cell_area(c.bud);
  return a;
}

Cell cell_from_lobes(const Eigen::Vector2d& mother, const Eigen::Vector2d& bud_centre, double bud) {
  Cell c;
  c.bud = bud;
  const double w = bud * bud / (1 + bud * bud);  // bud's share of the mass
  const Eigen::Vector2d r = (1 - w) * mother + w * bud_centre;
  c.x = r[0], c.y = r[1];
  const Eigen::Vector2d d = mother - bud_centre;
  c.theta = std::atan2(d[1], d[0]);
  return c;
}

}  // namespace cmp::cells2d
