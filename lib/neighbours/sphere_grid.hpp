#pragma once
// Linked cells for points on (or near) a sphere: a CellGrid over the sphere's bounding cube.
#include "neighbours/cell_grid.hpp"

#include <Eigen/Core>

namespace cmp::neighbours {

// A non-periodic CellGrid over the cube of side 2 radius centred on `centre`, holding every
// point of the sphere; points off the sphere (inside, or outside by any amount) are still
// handled (clamped into the boundary cells), so vertices that wander off the surface are fine.
// Distances are straight-line (chord) distances, not geodesic: a geodesic cutoff s is the chord
// 2 radius sin(s / (2 radius)). Cost: the grid has (2 radius/cutoff)^3 cells, of which only
// those near the surface hold points; with points about a cutoff apart that is ~(2/pi)
// radius/cutoff cells per point (e.g. 5.6 million cells, 22 MB, for 1e5 points), visited once
// per build. Beyond ~1e5 points the cap CellGrid::kMaxCells coarsens the cells (still correct).
// Throws cmp::UsageError unless radius > 0 and cutoff > 0.
CellGrid make_sphere_grid(double radius, double cutoff, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());

}  // namespace cmp::neighbours
