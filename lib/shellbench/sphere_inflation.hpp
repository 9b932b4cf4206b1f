#pragma once
// Benchmark B.5.1 (Fig. B.4A): a spherical shell of rest radius R0 inflated by dP, its radial
// strain eps_r = cbrt(V/V0) - 1 against the SVK sphere (elasticity/pressurised_sphere.hpp:
// the corrected B.81, the printed B.82 and the linear limit), for each stretching model.
// Loads are applied in increasing order, each relaxation starting from the previous state.
#include "shell/relax.hpp"
#include "shell/shell_parameters.hpp"

#include <string>
#include <vector>

namespace cmp::shellbench {

struct SphereInflationCase {
  int level = 4;                 // icosahedral subdivision level (4: 642 vertices, as the thesis)
  double radius = 2.5;           // R0 [m]
  shell::MaterialParameters material{25e6, 1.0 / 3.0, 0.1};  // E [Pa], nu, t [m] (thesis B.5.1)
  std::vector<std::string> models{"svk", "springs-kot", "springs-van-gelder"};
  std::vector<double> loads{1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2};  // dP/E
  double relative_tolerance = 1e-9;
};

struct SphereInflationRow {
  std::string model;
  double load = 0;              // dP/E
  double strain = 0;            // eps_r of the mesh, cbrt(V/V0) - 1
  double strain_corrected = 0;  // the SVK sphere (corrected B.81)
  double strain_printed = 0;    // the printed B.82
  double strain_linear = 0;     // small strain: dP R0 (1 - nu)/(2 E t)
  shell::RelaxResult relax;
};

std::vector<SphereInflationRow> sphere_inflation(const SphereInflationCase& c);

}  // namespace cmp::shellbench
