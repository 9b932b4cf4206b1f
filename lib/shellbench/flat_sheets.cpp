#include "shellbench/flat_sheets.hpp"

#include "shell/dead_load.hpp"
#include "shell/shell_model.hpp"

#include "mesh/disc_mesh.hpp"
#include "mesh/dual_areas.hpp"
#include "mesh/rectangle_mesh.hpp"

#include <cmath>

namespace cmp::shellbench {

using namespace cmp::shell;

namespace {
double mean_coordinate(const Eigen::VectorXd& x, const std::vector<int>& vs, int axis, double lo = -1e300,
                       double hi = 1e300, const mesh::VertexMatrix* rest = nullptr) {
  double sum = 0;
  int n = 0;
  for (int v : vs) {
    if (rest && ((*rest)(v, 0) < lo || (*rest)(v, 0) > hi)) continue;
    sum += x[3 * v + axis];
    ++n;
  }
  return sum / n;
}
}  // namespace

std::vector<PoissonRow> poisson_ratios(const std::vector<std::string>& models, const std::vector<double>& nus,
                                       double side, long vertices, double youngs_modulus, double thickness,
                                       double relative_tolerance) {
  const auto sheet = mesh::rectangle_mesh(side, side, vertices);
  const auto& rest = sheet.mesh;
  std::vector<PoissonRow> rows;
  for (const auto& model : models)
    for (double nu : nus) {
      ShellModel m;
      m.stretching = model;
      m.material = {youngs_modulus, nu, thickness};
      ShellSystem s = make_shell_system(rest, m);
      // Uniform traction sigma = 1e-3 Y on each loaded edge: each edge vertex carries the force
      // of half the edge segments next to it.
      const double traction = 1e-3 * youngs_modulus * thickness;
      std::vector<double> f(3 * rest.V.rows(), 0.0);
      const auto spread = [&](const std::vector<int>& edge, double sign) {
        for (std::size_t k = 0; k < edge.size(); ++k) {
          double share = 0;
          if (k > 0) share += 0.5 * (rest.V(edge[k], 1) - rest.V(edge[k - 1], 1));
          if (k + 1 < edge.size()) share += 0.5 * (rest.V(edge[k + 1], 1) - rest.V(edge[k], 1));
          f[3 * edge[k]] += sign * traction * share;
        }
      };
      spread(sheet.left, -1.0);
      spread(sheet.right, 1.0);
      s.add(std::make_unique<DeadLoad>(rest.V.rows(), f));
      RelaxParameters rp;
      rp.relative_tolerance = relative_tolerance;
      rp.force_scale = default_force_scale(rest, youngs_modulus, thickness);
      PoissonRow r;
      r.model = model;
      r.nu_input = nu;
      r.relax = relax(s, rp);
      const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(rest.V.data(), rest.V.size());
      const auto length = [&](const Eigen::VectorXd& x) {
        return mean_coordinate(x, sheet.right, 0) - mean_coordinate(x, sheet.left, 0);
      };
      const auto width = [&](const Eigen::VectorXd& x) {
        return mean_coordinate(x, sheet.top, 1, side / 3, 2 * side / 3, &rest.V) -
               mean_coordinate(x, sheet.bottom, 1, side / 3, 2 * side / 3, &rest.V);
      };
      r.strain_x = length(s.x) / length(x0) - 1.0;
      const double strain_y = width(s.x) / width(x0) - 1.0;
      r.nu_measured = -strain_y / r.strain_x;
      rows.push_back(r);
    }
  return rows;
}

std::vector<PlateResult> clamped_plate(const PlateCase& c, const std::vector<PlateLoad>& loads) {
  const auto disc = mesh::disc_mesh(c.radius, c.vertices);
  const auto& rest = disc.mesh;
  ShellModel m;
  m.stretching = c.stretching;
  m.bending = c.bending;
  m.material = c.material;
  ShellSystem s = make_shell_system(rest, m);
  std::vector<int> clamped;
  for (Eigen::Index v = 0; v < rest.V.rows(); ++v)
    if (rest.V.row(v).norm() >= c.radius - disc.spacing) clamped.push_back(static_cast<int>(v));
  s.fix(clamped);
  const Eigen::VectorXd dual = mesh::vertex_dual_areas(rest.V, rest.F);
  auto load = std::make_unique<DeadLoad>(rest.V.rows(), std::vector<double>(3 * rest.V.rows(), 0.0));
  DeadLoad* dead = load.get();
  s.add(std::move(load));
  // Out of the plane the flat start has no stiffness to probe: the mass comes from the
  // in-plane modes, which are the stiffest anyway.
  RelaxParameters rp;
  rp.relative_tolerance = c.relative_tolerance;
  rp.fire.max_iterations = c.max_iterations;
  rp.force_scale = default_force_scale(rest, c.material.youngs_modulus, c.material.thickness);
  std::vector<PlateResult> out;
  for (const auto& l : loads) {
    std::vector<double> f(3 * rest.V.rows(), 0.0);
    if (l.point) {
      f[3 * disc.centre + 2] = -l.value;
    } else {
      for (Eigen::Index v = 0; v < rest.V.rows(); ++v) f[3 * v + 2] = -l.value * dual[v];
    }
    dead->set_forces(f);
    PlateResult r;
    r.relax = relax(s, rp);
    for (Eigen::Index v = 0; v < rest.V.rows(); ++v) {
      if (s.fixed()[v]) continue;
      r.r.push_back(rest.V.row(v).norm());
      r.w.push_back(-s.x[3 * v + 2]);
    }
    r.w_max = -s.x[3 * disc.centre + 2];
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace cmp::shellbench
