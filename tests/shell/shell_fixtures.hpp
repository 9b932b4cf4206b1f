#pragma once
// Meshes and states shared by the shell tests.
#include "mesh/tri_mesh.hpp"
#include "shell/shell_parameters.hpp"
#include "spheremesh/subdivision.hpp"

#include <Eigen/Geometry>

#include <random>
#include <span>
#include <vector>

namespace cmp::shell::fixtures {

// The icosahedral sphere mesh of `level` with every vertex moved by a uniform random offset of
// up to `jitter` (times the radius) in each coordinate.
inline mesh::TriMesh perturbed_icosphere(int level, double jitter, unsigned seed, double radius = 1.0) {
  mesh::TriMesh m = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, radius);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * radius, jitter * radius);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    for (int r = 0; r < 3; ++r) m.V(i, r) += u(rng);
  return m;
}

// The flat state vector of a mesh's vertices (3 #V doubles).
inline std::vector<double> state(const mesh::VertexMatrix& V) {
  return std::vector<double>(V.data(), V.data() + V.size());
}

// x after the rigid motion x -> R x + t.
inline std::vector<double> moved(std::span<const double> x, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  std::vector<double> y(x.size());
  for (std::size_t i = 0; i + 2 < x.size(); i += 3) {
    const Eigen::Vector3d p = R * Eigen::Vector3d(x[i], x[i + 1], x[i + 2]) + t;
    y[i] = p.x(), y[i + 1] = p.y(), y[i + 2] = p.z();
  }
  return y;
}

// Two perturbed spheres of radius 1 (level 3) whose centres are 1.95 apart along x.
inline mesh::TriMesh two_shells(unsigned seed) {
  const auto a = perturbed_icosphere(3, 0.02, seed), b = perturbed_icosphere(3, 0.02, seed + 10);
  mesh::TriMesh m;
  m.V.resize(a.V.rows() + b.V.rows(), 3);
  m.F.resize(a.F.rows() + b.F.rows(), 3);
  m.V << a.V, b.V.rowwise() + Eigen::RowVector3d(1.95, 0, 0);
  m.F << a.F, b.F.array() + static_cast<int>(a.V.rows());
  return m;
}

// A deformed state: the rest mesh inflated by 8 % and jittered by 3 % of the radius.
inline std::vector<double> deformed(const mesh::TriMesh& rest, unsigned seed) {
  auto x = state(rest.V);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  for (double& v : x) v = 1.08 * v + u(rng);
  return x;
}

// Contacts: vertex spheres of radius 0.15, a contact distance of 0.2 to faces, and two walls at
// z = -+0.95 facing each other; on two_shells the deformed state overlaps both the other shell
// and the walls.
inline ContactParameters contact_parameters() {
  ContactParameters p;
  p.vertex_radius = 0.15;
  p.contact_distance = 0.2;
  p.youngs_modulus = 3.0;
  p.poisson_ratio = 0.3;
  p.wall_modulus = 10.0;
  p.wall_poisson_ratio = 0.4;
  p.walls = {Plane{Eigen::Vector3d(0, 0, -0.95), Eigen::Vector3d::UnitZ()},
             Plane{Eigen::Vector3d(0, 0, 0.95), -Eigen::Vector3d::UnitZ()}};
  return p;
}

}  // namespace cmp::shell::fixtures
