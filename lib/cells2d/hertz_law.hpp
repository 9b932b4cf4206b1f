#pragma once
// Hertz-like repulsion of lobes, V = (2/5) k delta^(5/2), force k delta^(3/2): the one Hertz
// law (forcefield/hertz.hpp) with its prefactor (4/3) E* sqrt(R*) taken as the unit k (the
// soft-sphere law of the thesis's Chapter 5 in this model's units; not the thesis's law for
// budding cells).
#include "cells2d/contact_law.hpp"
#include "forcefield/hertz.hpp"

namespace cmp::cells2d {

struct HertzLaw {
  static constexpr const char* name = "hertz";
  static constexpr const char* description =
      "V = (2/5) k delta^(5/2) (soft-sphere law, not the thesis's for budding cells)";
  static double energy(double overlap, const LawParameters&) { return hertz_energy(1.0, overlap); }
  static double force(double overlap, const LawParameters&) { return hertz_force(1.0, overlap); }
  static double range(const LawParameters&) { return 0; }
};

}  // namespace cmp::cells2d
