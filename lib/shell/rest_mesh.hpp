#pragma once
// Checks shared by the shell styles on the reference (rest) mesh they are built from.
#include "mesh/tri_mesh.hpp"

namespace cmp::shell {

// Throws cmp::UsageError (prefixed by `style`) when a face index is outside [0, #V), a rest
// position is not finite, or a rest triangle is degenerate (area <= 1e-14 times its longest
// edge squared).
void check_rest_mesh(const mesh::TriMesh& rest, const char* style);

}  // namespace cmp::shell
