#pragma once
// Elastic moduli of a static packing of cells in a periodic square box (thesis 3.4.3):
//   B = phi dP/dphi from a compression of the box by dphi = 1e-8 (centres scaled affinely,
//       then relaxed), P = tr(Pi)/2;
//   G = d Sigma_xy / d gamma from a simple shear x -> x + gamma y, gamma = 1e-6, with
//       Lees-Edwards images, then relaxed (Sigma = -Pi, the stress of S3.5).
// The packing itself is relaxed first with the same stopping rules, so the three states are
// minimised alike. Units: k and sigma.
#include "cells2d/cell.hpp"
#include "cells2d/contact_law.hpp"
#include "cells2d/packing_analysis.hpp"
#include "cells2d/relax.hpp"

#include <vector>

namespace cmp::cells2d {

struct ModuliParameters {
  double dphi = 1e-8;     // compression for B
  double strain = 1e-6;   // shear strain for G
  RelaxParameters relax = force_balance();
  // Relaxation to max |f_i| <= 1e-14 k sigma (rule (ii) kept): the energy-change rule stops
  // before a 1e-8 compression has relaxed.
  static RelaxParameters force_balance() {
    RelaxParameters r;
    r.force_tolerance = 1e-14;
    return r;
  }
};

struct Moduli {
  PackingAnalysis packing;  // of the relaxed packing
  double bulk = 0;          // B [k]
  double shear = 0;         // G [k]
  long iterations = 0;      // FIRE steps of the three relaxations
  bool relaxed = true;      // all three met max|f_i| <= tolerance within max_iterations
};

// cells are taken as they are (call canonical_cells first to match a file to the last digit).
Moduli measure_moduli(std::vector<Cell> cells, double box, const ContactLawStyle& law,
                      const ModuliParameters& parameters = {});

}  // namespace cmp::cells2d
