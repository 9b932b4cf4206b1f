#pragma once
// The force loop of ContactEngine (contacts.hpp) as a template over the contact law, so that
// the law's energy and force inline into it; contact_law.cpp instantiates it once per
// registered law. Only the table includes this header.
#include "cells2d/contacts.hpp"

#include <algorithm>

namespace cmp::cells2d {

template <class Law>
double ContactEngine::kernel(const ContactEngine& engine, const std::vector<Cell>& cells, double* force) {
  return engine.evaluate_with<Law>(cells, force);
}

template <class Law>
double ContactEngine::evaluate_with(const std::vector<Cell>& cells, double* force) const {
  const int lobes = static_cast<int>(radius_.size());
  std::fill(force, force + 3 * cells.size(), 0.0);
  const double* p = lobes_.data();  // row-major: lobe l at p[3 l], p[3 l + 1]
  double energy = 0;
  const LawParameters& law = parameters_;
  const double range = range_;
  for (int i = 0; i < lobes; ++i) {
    const int ci = i >> 1;
    const double xi = p[3 * i], yi = p[3 * i + 1], ri = radius_[i];
    double fx = 0, fy = 0, torque = 0;
    for (int j : candidates_of(i)) {
      const Eigen::Vector2d d = domain_.separation(Eigen::Vector2d(xi - p[3 * j], yi - p[3 * j + 1]));
      const double contact = ri + radius_[j], reach = contact + range, r2 = d[0] * d[0] + d[1] * d[1];
      if (r2 >= reach * reach || r2 == 0) continue;
      const double r = std::sqrt(r2), overlap = contact - r;
      energy += Law::energy(overlap, law);
      const double s = Law::force(overlap, law) / r, gx = s * d[0], gy = s * d[1];  // force on lobe i
      fx += gx, fy += gy;
      torque += offset_x_[i] * gy - offset_y_[i] * gx;
      const int cj = j >> 1;
      force[3 * cj] -= gx, force[3 * cj + 1] -= gy;
      force[3 * cj + 2] -= offset_x_[j] * gy - offset_y_[j] * gx;
    }
    force[3 * ci] += fx, force[3 * ci + 1] += fy, force[3 * ci + 2] += torque;
  }
  return energy;
}

}  // namespace cmp::cells2d
