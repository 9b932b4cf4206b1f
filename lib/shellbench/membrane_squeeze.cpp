#include "shellbench/membrane_squeeze.hpp"

#include "shell/shell_model.hpp"
#include "shell/shell_run.hpp"

#include "elasticity/membrane_contact.hpp"
#include "spheremesh/subdivision.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace cmp::shellbench {

using namespace cmp::shell;

std::vector<MembraneSqueezeRow> membrane_squeeze(const MembraneSqueezeCase& c) {
  const auto rest = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, c.level, c.radius);
  const elasticity::Sheet sheet{c.material.youngs_modulus, c.material.poisson_ratio, c.material.thickness};
  const double p_i = c.inflation * c.material.youngs_modulus;
  const elasticity::InflatedMembrane theory(sheet, c.radius, p_i);
  const auto solved = theory.sweep(c.compressions, elasticity::Fill::ConstantVolume);

  ShellModel m;
  m.material = c.material;
  m.pressure = "volume";
  m.load.turgor = p_i;
  m.walls = true;
  m.contact.vertex_radius = c.vertex_radius;
  m.contact.youngs_modulus = c.material.youngs_modulus;
  m.contact.poisson_ratio = c.material.poisson_ratio;
  ShellSystem s = make_shell_system(rest, m);
  RelaxParameters rp;
  rp.relative_tolerance = c.relative_tolerance;
  rp.force_scale = default_force_scale(rest, c.material.youngs_modulus, c.material.thickness);
  // Inflate at fixed P_i (no volume updates), then hold that volume.
  RelaxParameters inflate = rp;
  inflate.volume_tolerance = std::numeric_limits<double>::infinity();
  s.pressure()->set_target_volumes(s.pressure()->volumes(span_of(s.x)));
  relax(s, inflate);
  const std::vector<double> v_i = s.pressure()->volumes(span_of(s.x));
  s.pressure()->set_target_volumes(v_i);
  // The mesh's own inflated radius (the radius of a sphere of its volume): X then means the
  // same relative compression for mesh and theory (their radii differ by the mesh's 0.1 %).
  const double r_i = std::cbrt(3.0 * v_i.front() / (4.0 * std::numbers::pi)), scale = theory.force_scale();
  rp.volume_tolerance = c.volume_tolerance;
  std::vector<MembraneSqueezeRow> rows;
  for (std::size_t k = 0; k < c.compressions.size(); ++k) {
    MembraneSqueezeRow r;
    r.compression = c.compressions[k];
    const double eta = r_i * (1.0 - r.compression);
    r.gap = 2.0 * (eta + c.vertex_radius);
    s.walls()->set_walls(plates(0.0, r.gap));
    r.relax = relax(s, rp);
    const auto f = s.walls()->wall_forces(span_of(s.x));
    r.force = 0.5 * (f[0] + f[1]) / scale;
    r.pressure = s.pressure()->turgor() / p_i;
    r.force_theory = solved[k].force / scale;
    r.pressure_theory = solved[k].pressure / p_i;
    r.contact_radius_theory = solved[k].contact_radius / c.radius;
    r.volume_error = s.pressure()->volume_error(span_of(s.x));
    rows.push_back(r);
  }
  return rows;
}

}  // namespace cmp::shellbench
