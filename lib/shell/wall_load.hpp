#pragma once
// The load of a packing on the rigid walls of its box (thesis Fig. 4.5b): on every
// non-periodic axis a of the box [0, L), walls at 0 and L_a, each pushed by the vertices
// within R_v of it with the vertex-wall Hertz law (WallContacts of hertz_contacts.hpp).
//   wall pressure P = total normal force on the walls / total wall area
//   coverage Theta  = area of the faces whose three vertices touch a wall (the contact area
//                     rule of Fig. S2.7 and shellpack shell) / total wall area
// so P / Theta is the mean normal stress over the contact patches, which approaches the
// turgor for membranes (Fig. 4.5b: <Pi> ~ P / Theta).
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cmp::shell {

struct WallLoad {
  int walls = 0;             // 2 per non-periodic axis
  double force = 0;          // total normal force on the walls [force]
  double wall_area = 0;      // total area of the walls [length^2]
  double contact_area = 0;   // faces touching a wall [length^2]
  double pressure() const { return wall_area > 0 ? force / wall_area : 0.0; }
  double coverage() const { return wall_area > 0 ? contact_area / wall_area : 0.0; }
};

// The walls of the box [0, L) on its non-periodic axes: normals pointing inwards.
std::vector<Plane> box_walls(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic);

// The load on those walls of the vertices V (faces F) with R_v, E, nu and the wall material
// of p (p.walls is replaced by box_walls). No wall (every axis periodic): a zero WallLoad.
WallLoad wall_load(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const Eigen::Vector3d& lengths,
                   std::array<bool, 3> periodic, ContactParameters p);

}  // namespace cmp::shell
