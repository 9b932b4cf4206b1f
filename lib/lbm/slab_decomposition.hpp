#pragma once
// The split of a lattice over ranks (lbm/flow_solver.hpp): slabs of kBrickPlanes planes along
// the flow axis (lbm/layout.hpp: one contiguous node range each), whole slabs per rank, the
// ranges cut so that ranks hold nearly equal numbers of FLUID nodes (a porous medium is
// uneven along the axis; equal planes would leave the rank with the densest part behind).
#include <vector>

namespace cmp::lbm {

struct SlabDecomposition {
  std::vector<int> first_slab;  // rank r owns slabs [first_slab[r], first_slab[r + 1]); size ranks + 1
  int ranks() const { return static_cast<int>(first_slab.size()) - 1; }
  int owner(int slab) const;  // the rank holding a slab
};

// Slabs along an axis of `planes` planes.
int slab_count(int planes);

// Cuts slabs holding fluid[k] fluid nodes over `ranks` ranks: every rank gets at least one
// slab; cut r goes where the running fluid count comes nearest to r/ranks of the total.
// Throws cmp::UsageError "N ranks but only K slabs of 16 planes along the flow axis" when
// ranks exceed slabs.
SlabDecomposition decompose_slabs(const std::vector<long>& fluid, int ranks);

}  // namespace cmp::lbm
