#pragma once
// OFF (Object File Format), ASCII, triangles only: the mesh format of the toolkit.
//   OFF
//   # comment lines (anywhere before the counts line, and between records)
//   nV nF nE
//   x y z            (nV lines)
//   3 i j k          (nF lines, 0-based indices)
// The packing variant (DESIGN.md) adds, after the OFF line,
//   # box Lx Ly Lz
//   # periodic 1 1 1        (one 0/1 flag per axis)
//   # shells K n1 n2 ... nK (vertex counts, shell after shell; they add up to nV)
// and stays a valid OFF that MeshLab and ParaView open.
#include "mesh/tri_mesh.hpp"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cmp::io {

struct PackingInfo {
  std::optional<Eigen::Vector3d> box;      // # box Lx Ly Lz
  std::array<bool, 3> periodic{false, false, false};
  std::vector<int> shell_vertex_counts;    // # shells K n1 ... nK (empty: not a packing)
};

struct OffFile {
  mesh::VertexMatrix V;
  mesh::FaceMatrix F;
  PackingInfo packing;
  std::vector<std::string> comments;  // other comment lines, without the leading "# "
};

// Strict reader: wrong counts, a face index out of range, a non-number, a truncated file,
// a face that is not a triangle, NaN/Inf coordinates, inconsistent packing lines all throw
// cmp::InputError with the file and line. "-" reads standard input.
OffFile read_off(const std::string& path);

// Writes atomically (see AtomicOutput). Comments go right after the OFF line as "# <text>",
// then the packing lines when packing is given. Coordinates round-trip exactly.
void write_off(const std::string& path, const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
               const std::vector<std::string>& comments = {},
               const PackingInfo* packing = nullptr);

}  // namespace cmp::io
