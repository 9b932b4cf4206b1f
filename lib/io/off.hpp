#pragma once
// OFF (Object File Format), ASCII, triangles only: the mesh format of the toolkit.
// The dialects other programs write are read too, their extras checked as numbers and
// dropped: COFF (per-vertex colours "x y z r g b [a]", as MeshLab writes them), NOFF and
// CNOFF (normals), STOFF (texture coordinates), and per-face colours "3 i j k r g b [a]"
// (integers 0-255 or floats 0-1) in any of them.
//   OFF
//   # comment lines (anywhere before the counts line, and between records)
//   nV nF nE
//   x y z            (nV lines)
//   3 i j k          (nF lines, 0-based indices)
// The packing variant (docs/formats.md) adds, after the OFF line,
//   # box Lx Ly Lz
//   # periodic 1 1 1        (one 0/1 flag per axis)
//   # shells K n1 n2 ... nK (vertex counts, shell after shell; they add up to nV)
// and stays a valid OFF that MeshLab and ParaView open. Shell k owns the vertices
// [n1+...+n(k-1), n1+...+nk), and each face uses the vertices of one shell only.
#include "mesh/tri_mesh.hpp"
#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

// kMaxCoordinate (io/parse_number.hpp): the largest coordinate or box side the reader takes.
#include "io/parse_number.hpp"

namespace cmp::io {

struct PackingInfo {
  std::optional<Eigen::Vector3d> box;      // # box Lx Ly Lz
  long box_line = 0;                       // its line (for messages)
  std::array<bool, 3> periodic{false, false, false};
  std::vector<int> shell_vertex_counts;    // # shells K n1 ... nK (empty: not a packing)
};

struct OffFile {
  mesh::VertexMatrix V;
  mesh::FaceMatrix F;
  PackingInfo packing;
  std::vector<std::string> comments;  // other comment lines, without the leading "# "
  std::vector<long> comment_lines;    // the line of each comment (for messages)
};

class Input;

// Strict reader: wrong counts, a face index out of range, a non-number, a truncated file,
// a face that is not a triangle, NaN/Inf coordinates, inconsistent packing lines all throw
// cmp::InputError with the file and line. "-" reads standard input. Every count is checked
// before anything is allocated: '# shells' counts add up in 64 bits and must match nV, and a
// regular file must be large enough for the vertex and face lines the counts line claims
// (from a pipe, memory grows as lines arrive).
OffFile read_off(const std::string& path);
// Same, from an opened input (e.g. standard input whose format was told from its content).
OffFile read_off(Input& input);

// Writes atomically (see AtomicOutput). Comments go right after the OFF line as "# <text>",
// then the packing lines when packing is given. Coordinates round-trip exactly. Throws
// cmp::InputError(path, 0, ...) when the file cannot be written, else as the stream form.
void write_off(const std::string& path, const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
               const std::vector<std::string>& comments = {},
               const PackingInfo* packing = nullptr);

// Same, to a stream (no atomicity: the caller owns the stream). Throws std::invalid_argument
// when F indexes past V, a comment starts with a packing keyword (box, periodic, shells) or
// the packing is inconsistent with V and F (counts not adding up to #V, a face spanning two
// shells, a box side not positive); cmp::ComputationError when a coordinate is NaN or Inf.
void write_off(std::ostream& out, const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
               const std::vector<std::string>& comments = {},
               const PackingInfo* packing = nullptr);

// First vertex of each shell and one past the last: K+1 offsets, offsets[0] = 0,
// offsets[K] = #V. Shell k owns rows [offsets[k], offsets[k+1]) of V. Empty when
// shell_vertex_counts is empty.
std::vector<int> shell_vertex_offsets(const PackingInfo& packing);

}  // namespace cmp::io
