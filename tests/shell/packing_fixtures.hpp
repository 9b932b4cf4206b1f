#pragma once
// Synthetic packings of icosphere shells for the packing-analysis tests: copies of one mesh
// placed at given centres, as one mesh with the shell offsets of a packing OFF.
#include "mesh/tri_mesh.hpp"
#include "spheremesh/subdivision.hpp"

#include <Eigen/Geometry>

#include <vector>

namespace cmp::shell::fixtures {

struct SyntheticPacking {
  mesh::VertexMatrix V;
  mesh::FaceMatrix F;
  std::vector<int> offsets{0};
};

// Appends the mesh m moved by `centre` as the next shell.
inline void add_shell(SyntheticPacking& p, const mesh::TriMesh& m, const Eigen::Vector3d& centre) {
  const Eigen::Index v0 = p.V.rows(), f0 = p.F.rows();
  p.V.conservativeResize(v0 + m.V.rows(), 3);
  p.F.conservativeResize(f0 + m.F.rows(), 3);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) p.V.row(v0 + i) = m.V.row(i) + centre.transpose();
  p.F.bottomRows(m.F.rows()) = m.F.array() + static_cast<int>(v0);
  p.offsets.push_back(static_cast<int>(p.V.rows()));
}

// The icosphere of `level` and radius r, rotated so that its vertex of largest x lies on +x.
inline mesh::TriMesh icosphere_vertex_on_x(int level, double r) {
  auto m = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, r);
  Eigen::Index top = 0;
  m.V.col(0).maxCoeff(&top);
  const Eigen::Matrix3d R =
      Eigen::Quaterniond::FromTwoVectors(m.V.row(top).transpose(), Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) m.V.row(i) = (R * m.V.row(i).transpose()).transpose();
  return m;
}

// Lattice sites of n x n x n cubic cells of side a: simple cubic (one site per cell) or FCC
// (four).
inline std::vector<Eigen::Vector3d> cubic_lattice(int n, double a, bool fcc) {
  std::vector<Eigen::Vector3d> basis{{0, 0, 0}};
  if (fcc) basis = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<Eigen::Vector3d> sites;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& b : basis) sites.push_back(a * (Eigen::Vector3d(i, j, k) + b + Eigen::Vector3d::Constant(0.25)));
  return sites;
}

}  // namespace cmp::shell::fixtures
