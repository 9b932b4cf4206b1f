#include "cells2d/contact_law.hpp"

#include "cells2d/contact_kernel.hpp"
#include "cells2d/harmonic_law.hpp"
#include "cells2d/hertz_law.hpp"
#include "cells2d/sticky_law.hpp"

#include "core/registry.hpp"

namespace cmp::cells2d {

namespace {
template <class Law>
ContactLawStyle style() {
  return {Law::name, Law::description, &Law::energy, &Law::force, &Law::range, &ContactEngine::kernel<Law>};
}
}  // namespace

const std::vector<ContactLawStyle>& contact_laws() {
  static const std::vector<ContactLawStyle> table = {
      style<HarmonicLaw>(),
      style<HertzLaw>(),
      style<StickyLaw>(),
  };
  return table;
}

const ContactLawStyle& contact_law(const std::string& name) { return find_style(contact_laws(), name, "contact law"); }

}  // namespace cmp::cells2d
