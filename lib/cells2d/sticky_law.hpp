#pragma once
// The sticky cells of the chamber (thesis S2.14): the harmonic repulsion continued beyond
// contact into an attractive well of width Delta,
//   V = k delta^2 / 2 - k Delta^2 / 2   for delta > -Delta (zero beyond),
// so the force k delta pulls separated lobes together up to a gap Delta. The printed formula's
// constant -k Delta^2 / 2 is taken to hold only within the range (digest 2(d) 5): V is then
// continuous where a pair enters the range and the force alone carries the physics. With
// Delta = 0 (--attraction 0) it is the harmonic law.
#include "cells2d/contact_law.hpp"

namespace cmp::cells2d {

struct StickyLaw {
  static constexpr const char* name = "sticky";
  static constexpr const char* description =
      "V = k delta^2 / 2 - k Delta^2 / 2 for delta > -Delta: harmonic plus an attractive well of width "
      "Delta = --attraction (thesis S2.14)";
  static double energy(double overlap, const LawParameters& p) {
    return 0.5 * (overlap * overlap - p.attraction * p.attraction);
  }
  static double force(double overlap, const LawParameters&) { return overlap; }
  static double range(const LawParameters& p) { return p.attraction; }
};

}  // namespace cmp::cells2d
