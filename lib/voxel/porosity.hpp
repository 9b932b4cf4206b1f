#pragma once
// Porosity phi (in Chapter 5 of the thesis phi is the sample's porosity): from the geometry,
// 1 - particle volume / box volume (with the overlaps of spheres), and from a voxel image.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace cmp::voxel {

// Fraction of the voxels that are void (nonzero). 0 for an empty image.
double voxel_porosity(const std::vector<std::uint8_t>& pore);

struct SphereVolumes {
  double total = 0;         // sum of 4/3 pi r^3
  double pair_overlap = 0;  // sum of the lens volumes of every overlapping pair of spheres, periodic
                            // images included (per cell: a sphere and its own image count too)
  // Where the pair-lens correction stops being exact (inclusion-exclusion cut after pairs):
  long triple_overlaps = 0;  // triples of spheres (nearest images) with a common interior point
  long image_overlaps = 0;   // overlaps of a sphere with its own periodic images (counted per pair
                             // of images), and pairs that overlap through more than one image
  bool pair_correction_exact() const { return triple_overlaps == 0 && image_overlaps == 0; }
};
// Volumes of a sphere packing in a box [0, box), periodic along the flagged axes. The union of
// the spheres has volume total - pair_overlap exactly while pair_correction_exact(), and in any
// case between total - pair_overlap and total (Bonferroni), so 1 - (total - pair_overlap) /
// V_box bounds the porosity from above (and is >= 0) and 1 - total / V_box (the thesis's
// formula, negative once the spheres overlap enough) from below. O(S^2) pairs (fine for the
// few thousand spheres of a jammed packing) plus the triples among each sphere's overlapping
// neighbours.
SphereVolumes sphere_volumes(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const Eigen::Vector3d& box,
                             std::array<bool, 3> periodic);

// Whether three open balls (centres c1, c2, c3, radii r1, r2, r3) have a common point: the
// minimum over x of max_i (|x - c_i|^2 - r_i^2) is negative. That minimum lies at a centre, at
// a pair's radical point on the line of centres, or at the radical centre of the three (in
// their plane), so those seven candidates decide it exactly.
bool three_spheres_intersect(const Eigen::Vector3d& c1, double r1, const Eigen::Vector3d& c2, double r2,
                             const Eigen::Vector3d& c3, double r3);

// Volume of the intersection of two spheres of radii r1, r2 whose centres are d apart.
double lens_volume(double r1, double r2, double d);

}  // namespace cmp::voxel
