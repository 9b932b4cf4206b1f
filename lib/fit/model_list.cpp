#include "fit/model_list.hpp"

#include "fit/models.hpp"

#include <fmt/format.h>

namespace cmp::fit {

void write_model_list(std::ostream& out) {
  for (const auto& m : models()) {
    out << m.name << ": " << m.formula << "\n    " << m.source << "\n    domain " << m.domain
        << "; default columns --x " << fmt::format("{}", fmt::join(m.x_columns, " or ")) << " --y "
        << fmt::format("{}", fmt::join(m.y_columns, " or ")) << " (the first present)\n";
    for (const auto& p : m.params)
      out << fmt::format("    {:<11} {}{}\n", p.name, p.meaning,
                         p.fixed_by_default ? fmt::format(" (fixed at {} unless --free {})", p.start, p.name) : "");
  }
  out << "columns (as percolate, percolate sweep, lbflow and kcfit write them):\n"
         "    porosity             geometric porosity of a packing (percolate)\n"
         "    percolates           0/1: the void percolates along the flow axis (percolate, one row per run)\n"
         "    probability          fraction percolating per porosity bin, probability_error its binomial\n"
         "                         standard error (percolate sweep)\n"
         "    delta                voxel side in D_0\n"
         "    phi_c, phi_c_error   threshold per group (kcfit --model sigmoid --group-by delta)\n"
         "    permeability_delta2  permeability in units of delta^2 (lbflow's lattice units);\n"
         "                         permeability_d02 in D_0^2\n"
         "    rh_sites_d0          hydraulic radius in D_0 (percolate)\n"
         "    tortuosity           hydraulic tortuosity tau_H (lbflow)\n"
         "    <y>_error            standard error of y: weights the linear loss (--sigma)\n";
}

}  // namespace cmp::fit
