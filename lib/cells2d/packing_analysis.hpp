#pragma once
// What a static packing of budding cells is made of (thesis 3.4.3, 3.4.5): the pressure
// tensor, the contact network, rattlers, unconstrained buds, Z and the isostatic count
// Z_iso = 6 - 2 f_u - 2/(N - N_r).
//
// Definitions (the thesis leaves them open; docs/thesis-departures.md):
//   - a contact is a pair of overlapping lobes of different cells (overlap > 0);
//   - a rattler is a cell with fewer than 3 lobe contacts, or exactly 3 split 2 + 1 between
//     its lobes (no force balance is possible then); rattlers are removed repeatedly, each
//     removal taking its contacts from its neighbours, until none is left;
//   - among the other cells, every lobe without a contact is an unconstrained degree of
//     freedom (a bud of zero size counts: the cell is a disk free to turn); f_u = N_u/(N - N_r);
//   - Z = 2 N_c/(N - N_r) with N_c the contacts between non-rattlers.
#include "cells2d/cell.hpp"
#include "cells2d/contacts.hpp"

#include <Eigen/Core>

#include <vector>

namespace cmp::cells2d {

struct PackingAnalysis {
  int cells = 0;
  double area_fraction = 0;   // phi
  double energy = 0;          // V [k sigma^2]
  // Pressure tensor Pi = (1/A) sum_contacts d (x) f (d from lobe b to lobe a, f the force on a):
  // positive under compression; the thesis's stress S3.5 is -Pi. [k]
  Eigen::Matrix2d pressure_tensor = Eigen::Matrix2d::Zero();
  double pressure = 0;        // tr(Pi)/2 [k]
  int contacts = 0;           // all lobe contacts
  int rattlers = 0;           // N_r
  int unconstrained = 0;      // N_u: contact-less lobes of non-rattlers
  int network_contacts = 0;   // N_c: contacts between non-rattlers
  double Z = 0, f_u = 0, Z_iso = 0;  // 0 when every cell rattles
  double mean_rate = 0;       // Gamma = sum a_i gamma_i / sum a_i [gamma^0]
  std::vector<int> lobe_contacts;       // 2N: contacts of each lobe (all contacts)
  std::vector<double> lobe_force;       // 2N: sum of |F| on each lobe [k sigma]
  std::vector<char> rattler;            // N: 1 for a rattler

  // Pressure on a lobe: sum |F| over its perimeter pi sigma_lobe [k]; 0 for a bud of zero size.
  double lobe_pressure(const std::vector<Cell>& cells, int lobe) const;
};

PackingAnalysis analyse_packing(const std::vector<Cell>& cells, ContactEngine& engine);

// The bud pressure P_i = sum_j |F_ij| / (pi sigma_bud) of every cell (thesis 3.4.1) [k]; 0 for a
// bud of zero size (no perimeter yet).
std::vector<double> bud_pressures(const std::vector<Cell>& cells, ContactEngine& engine);

}  // namespace cmp::cells2d
