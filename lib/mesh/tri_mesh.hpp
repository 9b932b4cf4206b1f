#pragma once
// Triangle meshes as plain matrices, in the style of libigl:
//   V  #V by 3 vertex positions (row-major: one vertex per row, contiguous x y z)
//   F  #F by 3 vertex indices of each triangle, counter-clockwise seen from outside
// Every function of lib/mesh is a free function over (V, F).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, used by most of lib/mesh

namespace cmp::mesh {

using VertexMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using FaceMatrix = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using EdgeMatrix = Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>;

struct TriMesh {
  VertexMatrix V;
  FaceMatrix F;
};

}  // namespace cmp::mesh
