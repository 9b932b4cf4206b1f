#pragma once
// Contact laws between lobes of different cells: the energy styles of the cell model. A law
// gives the pair energy V(delta) and the repulsive force magnitude dV/d delta for an overlap
// delta = (sigma_ik + sigma_jl)/2 - |r_ik - r_jl| > 0 (zero otherwise), in units of k sigma^2
// and k sigma. One table (contact_laws()) lists every style; --list-models and --contact come
// from it, and the generic test harness checks each one (forces and torques = minus the
// numerical gradient of the energy).
#include <string>
#include <vector>

namespace cmp::cells2d {

// The harmonic repulsion of the thesis (S2.13, S3.2): V = k delta^2 / 2, force k delta.
struct HarmonicLaw {
  static double energy(double overlap) { return 0.5 * overlap * overlap; }
  static double force(double overlap) { return overlap; }
};

// Hertz-like repulsion V = (2/5) k delta^(5/2), force k delta^(3/2) (the soft-sphere law of
// the thesis's Chapter 5 in this model's units; not used by the thesis for budding cells).
struct HertzLaw {
  static double energy(double overlap);
  static double force(double overlap);
};

// Evaluates a law for a vector of overlaps (used by tests and reports; the force loops are
// templates instantiated per law, see contacts.hpp).
struct ContactLawStyle {
  std::string name;
  std::string description;
  int index;  // position in contact_laws(): selects the instantiated force loop
  double (*energy)(double overlap);
  double (*force)(double overlap);
};

// Every registered contact law, the thesis's first.
const std::vector<ContactLawStyle>& contact_laws();
// The law of that name; throws cmp::UsageError naming the choices otherwise.
const ContactLawStyle& contact_law(const std::string& name);
// Calls f(Law{}) with the law type of a style (the dispatch to a template).
template <class F>
decltype(auto) with_contact_law(const ContactLawStyle& style, F&& f) {
  if (style.index == 1) return f(HertzLaw{});
  return f(HarmonicLaw{});
}

}  // namespace cmp::cells2d
