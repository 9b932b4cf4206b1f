#pragma once
// Meshes and states shared by the shell tests.
#include "mesh/tri_mesh.hpp"
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

}  // namespace cmp::shell::fixtures
