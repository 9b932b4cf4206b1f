#pragma once
// The walls of the chamber of Chapter 2 (thesis 2.5, "Cells grow in a rectangular box of
// dimensions L_x x L_y with an outlet of width a"): the rectangle [0, width] x [0, height],
// whose bottom wall has an outlet of width a centred at x = width / 2 leading into a channel of
// that width and a given length (y from -channel to 0), open at its far end. The thesis leaves
// the outlet's place and the channel open; docs/jam2d.md says what was chosen and why.
//
// A lobe of radius rho whose centre lies at signed distance s from a wall (positive inside)
// overlaps it by delta = rho - s and feels the cell law's repulsion (V_wall = k delta^2 / 2 for
// the thesis's harmonic law; an attractive law's well is not applied to walls). The wall is
// straight segments plus the convex corners where segments end (the outlet's edges and the
// channel's far end): a lobe whose centre projects onto a segment sees that segment, one that
// projects onto none of a convex corner's segments sees the corner, so no contact is counted
// twice and the energy is continuous everywhere. At the chamber's four (concave) corners the
// walls continue as half-planes beyond their ends: a centre pushed past a corner, outside both
// walls' spans, is still pushed back by both.
#include "cells2d/cell.hpp"
#include "cells2d/contact_law.hpp"
#include "cells2d/contacts.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace cmp::cells2d {

struct ChamberGeometry {
  double width = 6;     // L_x [sigma]
  double height = 16;   // L_y [sigma]
  double outlet = 1.4;  // a [sigma]
  double channel = 2;   // length of the outlet channel [sigma]

  // Every problem as (option, message), empty when the geometry is sound.
  std::vector<std::pair<std::string, std::string>> problems() const;
  // Throws cmp::UsageError naming the first problem's option.
  void validate() const;
  double outlet_left() const { return 0.5 * (width - outlet); }
  double outlet_right() const { return 0.5 * (width + outlet); }
  // The chamber's wall length on which the pressure is measured (the outlet is open) [sigma].
  double wall_length() const { return 2 * width + 2 * height - outlet; }
  double area() const { return width * height; }
  // Where a cell's centre of mass may be: inside the chamber or the channel, or past the
  // channel's end (leaving), with a margin beyond the walls (a lobe pressed into a wall).
  bool contains(double x, double y, double margin = 0) const;
  bool in_chamber(double y) const { return y >= 0; }
  // The contact engine's box: the chamber, not periodic (cells in the channel, y < 0, fall
  // into the neighbour list's bottom row of bins).
  Domain domain() const {
    Domain d;
    d.lx = width, d.ly = height, d.periodic = false;
    return d;
  }
};

// One lobe touching a wall.
struct WallContact {
  int lobe;                // 2 i mother, 2 i + 1 bud of cell i
  double overlap;          // delta > 0 [sigma]
  double force;            // repulsive magnitude [k sigma]
  Eigen::Vector2d normal;  // unit, from the wall towards the lobe centre
  bool chamber;            // on the chamber's walls (pressure), not the channel's
};

class ChamberWalls {
 public:
  ChamberWalls(const ChamberGeometry& geometry, const ContactLawStyle& law);

  const ChamberGeometry& geometry() const { return geometry_; }
  // Energy of every lobe-wall overlap [k sigma^2]; adds F_x, F_y and the torque of each cell to
  // force (3 per cell).
  double add_forces(const std::vector<Cell>& cells, double* force) const;
  // The same for the lobes an engine has just placed (after its evaluate: the hot path).
  double add_forces(const ContactEngine& placed, double* force) const;
  double energy(const std::vector<Cell>& cells) const;
  // Calls f(const WallContact&) for every lobe touching a wall.
  template <class F>
  void for_each_contact(const std::vector<Cell>& cells, F&& f) const;

 private:
  struct Segment {
    Eigen::Vector2d a, tangent, normal;  // start, unit direction, unit inward normal
    double length;
    bool chamber;
    bool open_start, open_end;  // the wall continues beyond this end (a concave corner)
    // A channel wall has the channel on one side and solid beside the chamber's bottom wall on
    // the other: it holds lobes from the channel's side, up to a centre a radius behind it, and
    // leaves deeper ones to the bottom wall, which pushes them back into the chamber.
    bool thin;
  };
  struct Corner {
    Eigen::Vector2d at;
    int segments[2];  // the segments that end here (-1: none)
    bool chamber;
  };
  // Calls f(overlap, normal, chamber) for each wall a disk touches.
  template <class F>
  void touch(const Eigen::Vector2d& c, double radius, F&& f) const;
  bool projects_onto(const Segment& s, const Eigen::Vector2d& c) const {
    const double t = (c - s.a).dot(s.tangent);
    return (s.open_start || t >= 0) && (s.open_end || t <= s.length);
  }

  ChamberGeometry geometry_;
  const ContactLawStyle* law_;
  std::vector<Segment> segments_;
  std::vector<Corner> corners_;
};

// ---- templates ----

template <class F>
void ChamberWalls::touch(const Eigen::Vector2d& c, double radius, F&& f) const {
  // Far from every wall: the common case, decided without the segments. Only a lobe within a
  // radius of y = 0 (or below it) can touch the bottom walls, the outlet's edges or the
  // channel; the side and top walls are half-planes, tested directly (the same arithmetic as
  // (c - a) . normal, so the same bits) in the segments' order.
  const double W = geometry_.width, H = geometry_.height;
  const bool low = c[1] < radius;
  if (!low && c[0] > radius && c[0] < W - radius && c[1] < H - radius) return;
  const auto segment = [&](std::size_t k) {
    const Segment& s = segments_[k];
    if (!projects_onto(s, c)) return;
    // A centre behind a chamber wall is pushed back however deep (solid lies behind it).
    const double distance = (c - s.a).dot(s.normal), overlap = radius - distance;
    if (overlap > 0 && (!s.thin || distance > -radius)) f(overlap, s.normal, s.chamber);
  };
  if (low) segment(0);
  if (W - c[0] < radius) f(radius - (W - c[0]), segments_[1].normal, true);
  if (H - c[1] < radius) f(radius - (H - c[1]), segments_[2].normal, true);
  if (c[0] < radius) f(radius - c[0], segments_[3].normal, true);
  if (!low) return;
  for (std::size_t k = 4; k < segments_.size(); ++k) segment(k);
  for (const Corner& k : corners_) {
    bool in_band = false;
    for (int s : k.segments)
      if (s >= 0 && projects_onto(segments_[static_cast<std::size_t>(s)], c)) in_band = true;
    if (in_band) continue;
    const Eigen::Vector2d d = c - k.at;
    const double r2 = d.squaredNorm();
    if (r2 >= radius * radius || r2 == 0) continue;
    const double r = std::sqrt(r2);
    f(radius - r, Eigen::Vector2d(d / r), k.chamber);
  }
}

template <class F>
void ChamberWalls::for_each_contact(const std::vector<Cell>& cells, F&& f) const {
  const LawParameters repulsive;  // walls take the law's repulsion only
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const double radius = 0.5 * lobe_diameter(cells[i], k);
      if (radius <= 0) continue;
      const Eigen::Vector2d c = lobe_centre(cells[i], k);
      const int lobe = static_cast<int>(2 * i) + k;
      touch(c, radius, [&](double overlap, const Eigen::Vector2d& n, bool chamber) {
        f(WallContact{lobe, overlap, law_->force(overlap, repulsive), n, chamber});
      });
    }
}

}  // namespace cmp::cells2d
