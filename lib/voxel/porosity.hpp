#pragma once
// Porosity phi (in Chapter 5 "phi stands for the sample's porosity", thesis L658): from the
// geometry, 1 - sum of particle volumes / box volume (digest 4(a)), and from a voxel image.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace cmp::voxel {

// Fraction of the voxels that are void (nonzero). 0 for an empty image.
double voxel_porosity(const std::vector<std::uint8_t>& pore);

// Enclosed volume of every shell of a packing (mesh::enclosed_volume, divergence theorem).
//   V        #V by 3, each shell in one periodic image (see unwrap_shells)
//   F        #F by 3 triangles, each within one shell
//   offsets  K+1 vertex offsets (io::shell_vertex_offsets): shell k owns [offsets[k], offsets[k+1])
// Result: K signed volumes (positive for outward faces).
std::vector<double> shell_volumes(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets);

struct SphereVolumes {
  double total = 0;         // sum of 4/3 pi r^3
  double pair_overlap = 0;  // sum over overlapping pairs of their lens volume (minimum image)
};
// Volumes of a sphere packing in a box [0, box), periodic along the flagged axes. 1 - (total -
// pair_overlap) / V_box is exact while no point lies in three spheres; 1 - total / V_box is
// the thesis's formula. O(S^2) pairs (fine for the few thousand spheres of a jammed packing).
SphereVolumes sphere_volumes(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const Eigen::Vector3d& box,
                             std::array<bool, 3> periodic);

// Volume of the intersection of two spheres of radii r1, r2 whose centres are d apart.
double lens_volume(double r1, double r2, double d);

}  // namespace cmp::voxel
