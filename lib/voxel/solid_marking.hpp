#pragma once
// Projection of a packing onto the lattice (thesis 5.2.2, Fig. 5.1): voxels that hold any part
// of a particle become solid (0) in a pore image whose voxels start as void (1). Shells are
// marked by their vertices (the thesis's method, which leaks once delta is below the edge
// length) or by their triangles (conservative triangle-voxel overlap, the default), optionally
// thickened; spheres exactly. Along periodic axes every voxel is tested against every image of an
// element (the nearest image for spheres), so elements of any size, even larger than the box,
// are marked wherever they reach.
#include "mesh/tri_mesh.hpp"
#include "voxel/grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace cmp::voxel {

// How shells become solid voxels.
enum class ShellMarking {
  Vertices,   // voxels holding a vertex (thesis 5.2.2)
  Triangles,  // voxels a triangle touches (separating-axis test): no holes at any delta
};
// "vertices" or "triangles"; throws cmp::UsageError otherwise.
ShellMarking shell_marking_from_name(const std::string& name);
std::string shell_marking_name(ShellMarking m);

// How spheres become solid voxels.
enum class SphereMarking {
  Overlap,  // voxels with any point closer than r to the centre (Fig. 5.1: "any part")
  Centre,   // voxels whose centre is closer than r to the sphere's centre
};
SphereMarking sphere_marking_from_name(const std::string& name);  // "overlap" or "centre"
std::string sphere_marking_name(SphereMarking m);

// Marks the shells of a mesh packing solid in pore (grid.size() bytes, 1 = void, 0 = solid).
//   V          #V by 3 vertex positions [length units], anywhere: wrapped into the box along
//              periodic axes, clipped to it along the others
//   F          #F by 3 triangles (ignored for Vertices); a triangle's corners must be given in
//              one periodic image (unwrap each shell first, see unwrap_shells)
//   thickness  r >= 0: also marks voxels within max-norm distance r of a vertex / triangle
//              (the voxel box grown by r on every side overlaps it), e.g. half the shell
//              thickness or the vertex radius R_v
// Parallel over triangles (or vertices); the result does not depend on the thread count.
void mark_shells(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const VoxelGrid& grid, ShellMarking method,
                 double thickness, std::vector<std::uint8_t>& pore);

// Marks spheres solid in pore (see mark_shells): a voxel is solid when the nearest image of
// the sphere (cmp::minimum_image along each periodic axis) reaches it, at any radius.
//   centres  #S by 3 [length units]; radii  #S radii (> 0) [length units]
void mark_spheres(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const VoxelGrid& grid,
                  SphereMarking method, std::vector<std::uint8_t>& pore);

}  // namespace cmp::voxel
