#include "shell/shell_packing.hpp"

#include "shell/shell_partition.hpp"
#include "shell/shell_run.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"
#include "core/random.hpp"
#include "io/csv.hpp"
#include "mesh/enclosed_volume.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace cmp::shell {

io::SpherePackingFrame read_start_packing(const std::string& path) {
  auto frames = io::read_sphere_packing_xyz(path, io::PbcRule::require_all);
  io::SpherePackingFrame p = std::move(frames.front());
  const int n = p.size();
  if (n < 2) throw InputError(path, p.line, "a packing of shells needs at least 2 spheres");
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j) {
      Eigen::Vector3d d = p.centres.row(i) - p.centres.row(j);
      for (int a = 0; a < 3; ++a) d[a] = minimum_image(d[a], p.box[a]);
      if (d.norm() < 0.5 * (p.radii[i] + p.radii[j]))
        throw InputError(path, p.line + 2 + i,
                         "sphere " + std::to_string(i + 1) + " overlaps sphere " + std::to_string(j + 1) +
                             " by more than half their radii (centres " + io::format_number(d.norm()) +
                             " apart): a duplicated particle, not a jammed packing");
    }
  return p;
}

mesh::TriMesh normalised_cell(const mesh::TriMesh& m, const std::string& path) {
  check_closed_shell_mesh(m, path);
  if (shell_partition(m.F, static_cast<int>(m.V.rows())).shell_count != 1)
    throw InputError(path, 0, "the cell mesh must be one closed shell (it has several connected components)");
  mesh::TriMesh c = m;
  const Eigen::RowVector3d centroid = c.V.colwise().mean();
  c.V.rowwise() -= centroid;
  const double v = mesh::enclosed_volume(c.V, c.F);
  const double d = std::cbrt(6.0 * v / std::numbers::pi);
  c.V /= d;
  return c;
}

namespace {

// A rotation uniform over SO(3) (Shoemake 1992) from three uniform numbers.
Eigen::Matrix3d random_rotation(Random& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1), t2 = 2 * std::numbers::pi * u2, t3 = 2 * std::numbers::pi * u3;
  const Eigen::Quaterniond q(b * std::cos(t3), a * std::sin(t2), a * std::cos(t2), b * std::sin(t3));
  return q.normalized().toRotationMatrix();
}

}  // namespace

ShellPacking place_shells(const io::SpherePackingFrame& spheres, const mesh::TriMesh& cell, double rest_diameter,
                          double envelope, std::uint64_t seed) {
  const int n = spheres.size();
  const Eigen::Index nv = cell.V.rows(), nf = cell.F.rows();
  const double mean_radius = spheres.radii.mean();
  const double unit = 2.0 * mean_radius / (1.0 + envelope);  // D_0 in the file's length unit
  ShellPacking p;
  p.box = spheres.box / unit;
  p.periodic = spheres.pbc;
  p.mesh.V.resize(n * nv, 3);
  p.mesh.F.resize(n * nf, 3);
  for (int i = 0; i < n; ++i) {
    Random rng(seed, static_cast<std::uint64_t>(i));
    const Eigen::Matrix3d R = random_rotation(rng);
    const double factor = spheres.radii[i] / mean_radius;
    const Eigen::Vector3d centre = spheres.centres.row(i).transpose() / unit;
    for (Eigen::Index v = 0; v < nv; ++v)
      p.mesh.V.row(i * nv + v) = (R * (rest_diameter * factor * cell.V.row(v).transpose()) + centre).transpose();
    p.mesh.F.middleRows(i * nf, nf) = cell.F.array() + static_cast<int>(i * nv);
    p.shell_vertex_counts.push_back(static_cast<int>(nv));
    p.size_factors.push_back(factor);
  }
  return p;
}

double rest_diameter_for_inflated(const mesh::TriMesh& cell, const ShellModel& model, const RelaxParameters& relax) {
  ShellModel m = model;
  m.pressure = "turgor";
  m.walls = m.shell_contacts = false;
  double d = 1.0;
  for (int k = 0; k < 3; ++k) {
    mesh::TriMesh rest = cell;
    rest.V *= d;
    ShellSystem s = make_shell_system(rest, m);
    RelaxParameters rp = relax;
    rp.fire.max_iterations = std::max(rp.fire.max_iterations, 1'000'000L);  // one shell: not the packing's cap
    rp.force_scale = default_force_scale(rest, m.material.youngs_modulus, m.material.thickness);
    const auto r = shell::relax(s, rp);
    if (!r.converged())
      throw ComputationError("inflating the cell template at Pi_0 did not converge (" + relax_stop_name(r.stop) +
                             ", residual " + io::format_number(r.residual) + ")");
    const double v = s.pressure()->volumes(span_of(s.x)).front();
    d /= std::cbrt(6.0 * v / std::numbers::pi);
  }
  return d;
}

double max_circumradius(const mesh::TriMesh& cell) {
  double most = 0;
  for (Eigen::Index f = 0; f < cell.F.rows(); ++f) {
    const Eigen::Vector3d a = cell.V.row(cell.F(f, 0)), b = cell.V.row(cell.F(f, 1)), c = cell.V.row(cell.F(f, 2));
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    const double area2 = (b - a).cross(c - a).norm();  // twice the area
    most = std::max(most, ab * bc * ca / (2.0 * area2));
  }
  return most;
}

}  // namespace cmp::shell
