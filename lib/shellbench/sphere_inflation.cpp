#include "shellbench/sphere_inflation.hpp"

#include "shell/shell_model.hpp"

#include "elasticity/pressurised_sphere.hpp"
#include "spheremesh/subdivision.hpp"

#include <cmath>

namespace cmp::shellbench {

using namespace cmp::shell;

std::vector<SphereInflationRow> sphere_inflation(const SphereInflationCase& c) {
  const auto rest = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, c.level, c.radius);
  const elasticity::Sheet sheet{c.material.youngs_modulus, c.material.poisson_ratio, c.material.thickness};
  std::vector<SphereInflationRow> rows;
  for (const auto& model : c.models) {
    ShellModel m;
    m.stretching = model;
    m.pressure = "turgor";
    m.material = c.material;
    ShellSystem s = make_shell_system(rest, m);
    const double v0 = s.pressure()->volumes(span_of(s.x)).front();
    RelaxParameters rp;
    rp.relative_tolerance = c.relative_tolerance;
    rp.force_scale = default_force_scale(rest, c.material.youngs_modulus, c.material.thickness);
    for (double load : c.loads) {
      const double dp = load * c.material.youngs_modulus;
      s.pressure()->set_turgor(dp);
      SphereInflationRow r;
      r.model = model;
      r.load = load;
      r.relax = relax(s, rp);
      r.strain = std::cbrt(s.pressure()->volumes(span_of(s.x)).front() / v0) - 1.0;
      r.strain_corrected = elasticity::sphere_stretch(sheet, c.radius, dp) - 1.0;
      r.strain_printed = elasticity::sphere_strain_printed(sheet, c.radius, dp);
      r.strain_linear = elasticity::sphere_strain_linear(sheet, c.radius, dp);
      rows.push_back(r);
    }
  }
  return rows;
}

}  // namespace cmp::shellbench
