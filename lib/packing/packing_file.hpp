#pragma once
// A packing as the tools read it (percolate, lbflow, shellpack analyze): shells from a packing
// OFF (docs/formats.md: '# box', '# periodic', '# shells') or spheres from an extended XYZ frame
// (Lattice, radius column), with the length D_0 that delta is measured in.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace cmp::io {
class Input;
}

namespace cmp::packing {

// The largest box side of a packing OFF, in D0: larger is refused when read.
inline constexpr double kMaxBoxInD0 = 1e6;

struct Packing {
  enum class Kind { Shells, Spheres };
  Kind kind = Kind::Shells;
  std::string file;
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  // the box is [0, box) [length units]
  std::array<bool, 3> periodic{true, true, true};
  // Shells: vertices (each shell unwrapped into one periodic image), triangles, K+1 offsets.
  mesh::VertexMatrix V;
  mesh::FaceMatrix F;
  std::vector<int> shell_offsets;
  // Spheres: centres and radii (already multiplied by the scale factor).
  mesh::VertexMatrix centres;
  Eigen::VectorXd radii;
  double scale = 1;  // radius scale factor applied
  // The unit of delta [length units] and where it came from: "option" (--d0), "file" (a
  // '# D0=' comment of the OFF, a D0= pair of the XYZ comment line), "shell_volume" (the
  // diameter of the sphere of the mean shell volume: the initial diameter when shells keep
  // their volume, as in the thesis), "mean_diameter" (mean unscaled sphere diameter).
  double d0 = 1;
  std::string d0_source;
  // Shells: the OFF's other comment lines (io::OffFile::comments) and their line numbers.
  std::vector<std::string> comments;
  std::vector<long> comment_lines;

  int particles() const { return kind == Kind::Shells ? static_cast<int>(shell_offsets.size()) - 1 : static_cast<int>(centres.rows()); }
};

// The largest radius factor (--scale) that a sphere packing's spheres can take and still mean
// something: the largest sphere's radius at most half the box's diagonal. Beyond it that
// sphere covers every point of the box (no point of a periodic box is farther from a centre),
// so every larger scale gives the same porosity 0, while the work of marking it grows as the
// cube of the scale (minutes at 1e3, out of memory at 1e18, nonsense from overflow at 1e20,
// porosities of 1e90 in lbflow). p as read (radii already scaled by p.scale).
double max_scale(const Packing& p);
// Throws cmp::UsageError("--scale 1e3: the largest sphere's radius would be 400, more than
// half the box's diagonal 3.464 (...): at most 8.66 for j.xyz") when scale (> 1) exceeds
// max_scale(p); scale_text as typed. A scale of at most 1 is never refused.
void check_scale(const Packing& p, double scale, const std::string& scale_text);

struct PackingReadOptions {
  double scale = 1;  // spheres: radii are multiplied by it (> 0, at most max_scale: UsageError)
  double d0 = 0;     // > 0: D_0 given by the user, overriding the file
};

// Reads path ("-" = standard input), telling the format from the content (io::Input::format):
// a packing OFF gives one Packing (shells), an extended XYZ one Packing per frame (spheres,
// read by io::read_sphere_packing_xyz with PbcRule::as_in_file: the file's pbc flags are
// honoured). A D0 from the file ('# D0=' comment of the OFF, D0= of the XYZ comment line) is
// read strictly ("2.0abc" and "0x2" are errors at their line). Throws cmp::InputError(file,
// line, ...) for: content that is neither OFF nor extended XYZ, an OFF without '# box' (line
// 1) or without triangles, everything io::read_off and io::read_sphere_packing_xyz reject
// (no diagonal Lattice, no radius column, a radius <= 0, a duplicated particle, a frame
// without spheres, ...).
std::vector<Packing> read_packings(const std::string& path, const PackingReadOptions& options = {});
// Same, from an opened input.
std::vector<Packing> read_packings(io::Input& input, const PackingReadOptions& options = {});
// The last of read_packings(path, options) (an OFF's only packing, an XYZ's last frame).
Packing read_packing(const std::string& path, const PackingReadOptions& options = {});

// Moves every vertex of each shell to the periodic image nearest to its neighbours along
// the mesh edges (breadth first from the shell's first vertex), so that no triangle spans
// the box. Needs edges shorter than half the box. Vertices in no triangle stay put.
void unwrap_shells(mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets,
                   const Eigen::Vector3d& box, std::array<bool, 3> periodic);

}  // namespace cmp::packing
