#pragma once
// The harmonic repulsion of the thesis (S2.13, S3.2): V = k delta^2 / 2, force k delta, for an
// overlap delta of two lobes (contact_law.hpp), in units of k sigma^2 and k sigma.
#include "cells2d/contact_law.hpp"

namespace cmp::cells2d {

struct HarmonicLaw {
  static constexpr const char* name = "harmonic";
  static constexpr const char* description = "V = k delta^2 / 2 between overlapping lobes (thesis S3.2)";
  static double energy(double overlap, const LawParameters&) { return 0.5 * overlap * overlap; }
  static double force(double overlap, const LawParameters&) { return overlap; }
  static double range(const LawParameters&) { return 0; }
};

}  // namespace cmp::cells2d
