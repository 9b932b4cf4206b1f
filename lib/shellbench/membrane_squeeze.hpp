#pragma once
// Benchmark B.6 (Fig. B.9): a spherical SVK membrane (no bending) of rest radius R0 inflated by
// P_i and filled incompressibly (the "volume" pressure), then squeezed between two rigid
// plates. The mesh's plate force and turgor against the shooting solution of
// elasticity/membrane_contact.hpp. The plates act through Hertz vertex spheres of radius R_v:
// the membrane's mid-surface stops about R_v short of a plate, so a plate gap g compares with
// the analytic half gap eta_bar = g/2 - R_v. Compression X = 1 - eta_bar/R_i (R_i the radius
// of the sphere of the inflated mesh's volume), F^ = F/(E t R0), P* = P/P_i.
#include "shell/relax.hpp"
#include "shell/shell_parameters.hpp"

#include <vector>

namespace cmp::shellbench {

struct MembraneSqueezeCase {
  int level = 5;                  // icosahedral level (5: 2562 vertices)
  double radius = 1.0;            // R0
  shell::MaterialParameters material{1.0, 0.5, 0.04};  // E, nu, t (t/R0 = 0.04, nu = 0.5: Fig. B.9)
  double inflation = 0.0025;      // P_i/E
  double vertex_radius = 0.01;    // R_v [length]
  std::vector<double> compressions{0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3};  // X, increasing
  double relative_tolerance = 1e-7;
  double volume_tolerance = 1e-5;  // tighter than the thesis's 0.1 %: P moves 3 % per 0.1 % of volume here
};

struct MembraneSqueezeRow {
  double compression = 0;        // X
  double gap = 0;                // plate gap g [length]
  double force = 0;              // F^ of the mesh (mean of the two plates)
  double force_theory = 0;       // F^ of the shooting solution
  double pressure = 0;           // P* of the mesh
  double pressure_theory = 0;    // P* of the shooting solution
  double contact_radius_theory = 0;  // r_c / R0
  double volume_error = 0;       // |V - V_i|/V_i of the mesh
  shell::RelaxResult relax;
};

std::vector<MembraneSqueezeRow> membrane_squeeze(const MembraneSqueezeCase& c);

}  // namespace cmp::shellbench
