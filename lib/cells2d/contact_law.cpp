#include "cells2d/contact_law.hpp"

#include "core/registry.hpp"

#include <cmath>

namespace cmp::cells2d {

double HertzLaw::energy(double overlap) { return 0.4 * overlap * overlap * std::sqrt(overlap); }
double HertzLaw::force(double overlap) { return overlap * std::sqrt(overlap); }

const std::vector<ContactLawStyle>& contact_laws() {
  static const std::vector<ContactLawStyle> table = {
      {"harmonic", "V = k delta^2 / 2 between overlapping lobes (thesis S3.2)", 0, &HarmonicLaw::energy,
       &HarmonicLaw::force},
      {"hertz", "V = (2/5) k delta^(5/2) (soft-sphere law, not the thesis's for budding cells)", 1,
       &HertzLaw::energy, &HertzLaw::force},
  };
  return table;
}

const ContactLawStyle& contact_law(const std::string& name) {
  return find_style(contact_laws(), name, "contact law");
}

}  // namespace cmp::cells2d
