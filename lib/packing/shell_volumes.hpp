#pragma once
// The volume each shell of a packing encloses: what its porosity, its volume fraction and its
// D0 rule are computed from.
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::packing {

// Enclosed volume of every shell of a packing (mesh::enclosed_volume, divergence theorem).
//   V        #V by 3, each shell in one periodic image (see unwrap_shells)
//   F        #F by 3 triangles, each within one shell
//   offsets  K+1 vertex offsets (io::shell_vertex_offsets): shell k owns [offsets[k], offsets[k+1])
// Result: K signed volumes (positive for outward faces).
std::vector<double> shell_volumes(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets);

}  // namespace cmp::packing
