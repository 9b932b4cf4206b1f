#pragma once
// Do shells pass through each other? A vertex of one shell inside another shell's closed
// surface (mesh/inside_query.hpp: crossings of a ray over a grid of the faces, the winding
// number where a crossing is too close to call), with the minimum image in a periodic
// box: each shell is taken whole (its vertices unwrapped, as the compress driver keeps them)
// and a vertex of another shell is brought to the image nearest the shell's centre first.
// Only vertices within a shell's bounding sphere are tested, each against the few faces over
// it; shells run on all threads (the count is the same).
#include "shell/shell_partition.hpp"

#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace cmp::shell {

struct Penetration {
  int vertex;  // a vertex of shell `vertex_shell`...
  int vertex_shell;
  int shell;   // ...inside this shell
};

// Every vertex lying inside another shell at x (3 #V doubles), for the faces F partitioned
// into shells by `shells`; box: sides of a box periodic along the flagged axes, or none.
// Shells must be closed and outward-oriented. Ordered by shell, then vertex.
std::vector<Penetration> penetrations(const Eigen::VectorXd& x, const mesh::FaceMatrix& F, const ShellPartition& shells,
                                      const std::optional<Eigen::Vector3d>& box,
                                      std::array<bool, 3> periodic = {true, true, true});

}  // namespace cmp::shell
