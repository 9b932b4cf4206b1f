#pragma once
// The shells of a mesh: its connected components (faces sharing a vertex belong to one shell).
// A packing OFF holds many shells in one mesh; every per-shell quantity (volume, turgor,
// which vertex pairs may touch) follows this partition, so one state vector serves one shell
// or fifty alike.
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

struct ShellPartition {
  int shell_count = 0;
  std::vector<int> vertex_shell;  // #V: the shell of each vertex (-1 for a vertex in no face)
  std::vector<int> face_shell;    // #F: the shell of each face
};

// Components numbered in the order of their lowest vertex index (shells of a packing OFF come
// out in file order). O(#F alpha). Face indices must lie in [0, vertex_count).
ShellPartition shell_partition(const mesh::FaceMatrix& F, int vertex_count);

}  // namespace cmp::shell
