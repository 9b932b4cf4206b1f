#include "cells2d/chamber_walls.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <string>

namespace cmp::cells2d {

std::vector<std::pair<std::string, std::string>> ChamberGeometry::problems() const {
  std::vector<std::pair<std::string, std::string>> out;
  const auto require = [&](bool ok, const char* option, const char* what) {
    if (!ok) out.emplace_back(option, what);
  };
  // A mother lobe (diameter sigma) must fit into the chamber and through the outlet.
  require(std::isfinite(width) && width >= 1, "--width", "must be at least 1 sigma (a cell's diameter)");
  require(std::isfinite(height) && height >= 1, "--height", "must be at least 1 sigma (a cell's diameter)");
  require(std::isfinite(outlet) && outlet > 0, "--outlet", "must be positive");
  if (outlet >= width)
    require(false, "--outlet", "must be narrower than the chamber's wall (--width)");
  else  // the side walls' planes, continued past the corners, must stay a radius from the channel
    require(!(width - outlet < 1), "--outlet", "must leave at least sigma/2 of wall on each side (at most --width - 1)");
  require(std::isfinite(channel) && channel > 0, "--channel", "must be positive");
  require(!(width * height > 1e6), "--width", "times --height must be at most 1e6 sigma^2 (a chamber holds of the order of its area in cells)");
  return out;
}

void ChamberGeometry::validate() const {
  const auto p = problems();
  if (!p.empty()) throw UsageError(p.front().first + ": " + p.front().second);
}

bool ChamberGeometry::contains(double x, double y, double margin) const {
  if (y >= -margin && x >= -margin && x <= width + margin && y <= height + margin) return true;
  if (y < -channel) return true;  // past the channel: leaving
  return x >= outlet_left() - margin && x <= outlet_right() + margin;
}

ChamberWalls::ChamberWalls(const ChamberGeometry& g, const ContactLawStyle& law) : geometry_(g), law_(&law) {
  g.validate();
  const double W = g.width, H = g.height, x0 = g.outlet_left(), x1 = g.outlet_right(), d = g.channel;
  const auto segment = [&](Eigen::Vector2d a, Eigen::Vector2d b, bool chamber, bool open_start, bool open_end) {
    const Eigen::Vector2d t = b - a;
    const double length = t.norm();
    const Eigen::Vector2d u = t / length;
    // Segments run with the inside on their left.
    segments_.push_back({a, u, Eigen::Vector2d(-u[1], u[0]), length, chamber, open_start, open_end, !chamber});
  };
  // Counter-clockwise around the inside: bottom right of the outlet, right, top, left, bottom
  // left of the outlet, then down the channel's left wall and up its right wall. Ends at the
  // chamber's corners are open (concave), ends at the outlet and the channel's end closed.
  segment({x1, 0}, {W, 0}, true, false, true);      // 0
  segment({W, 0}, {W, H}, true, true, true);        // 1
  segment({W, H}, {0, H}, true, true, true);        // 2
  segment({0, H}, {0, 0}, true, true, true);        // 3
  segment({0, 0}, {x0, 0}, true, true, false);      // 4
  segment({x0, 0}, {x0, -d}, false, false, false);  // 5
  segment({x1, -d}, {x1, 0}, false, false, false);  // 6
  // The convex corners: the outlet's edges and the channel's open end.
  corners_.push_back({{x0, 0}, {4, 5}, true});
  corners_.push_back({{x1, 0}, {6, 0}, true});
  corners_.push_back({{x0, -d}, {5, -1}, false});
  corners_.push_back({{x1, -d}, {6, -1}, false});
}

double ChamberWalls::add_forces(const std::vector<Cell>& cells, double* force) const {
  const LawParameters repulsive;
  double energy = 0;
  for_each_contact(cells, [&](const WallContact& w) {
    const std::size_t i = static_cast<std::size_t>(w.lobe >> 1);
    energy += law_->energy(w.overlap, repulsive);
    const Eigen::Vector2d f = w.force * w.normal;
    const Eigen::Vector2d arm = lobe_centre(cells[i], w.lobe & 1) - Eigen::Vector2d(cells[i].x, cells[i].y);
    force[3 * i] += f[0], force[3 * i + 1] += f[1];
    force[3 * i + 2] += arm[0] * f[1] - arm[1] * f[0];
  });
  return energy;
}

double ChamberWalls::add_forces(const ContactEngine& placed, double* force) const {
  const LawParameters repulsive;
  double energy = 0;
  const int lobes = placed.lobe_count();
  for (int l = 0; l < lobes; ++l) {
    const double radius = placed.lobe_radius(l);
    if (radius <= 0) continue;
    touch(placed.lobe_position(l), radius, [&](double overlap, const Eigen::Vector2d& n, bool) {
      energy += law_->energy(overlap, repulsive);
      const Eigen::Vector2d f = law_->force(overlap, repulsive) * n, arm = placed.lobe_offset(l);
      const std::size_t i = static_cast<std::size_t>(l >> 1);
      force[3 * i] += f[0], force[3 * i + 1] += f[1];
      force[3 * i + 2] += arm[0] * f[1] - arm[1] * f[0];
    });
  }
  return energy;
}

double ChamberWalls::energy(const std::vector<Cell>& cells) const {
  const LawParameters repulsive;
  double energy = 0;
  for_each_contact(cells, [&](const WallContact& w) { energy += law_->energy(w.overlap, repulsive); });
  return energy;
}

}  // namespace cmp::cells2d
