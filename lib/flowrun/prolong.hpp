#pragma once
// The steady flow of one refinement M, prolonged onto a finer one as the start of its run: near
// the percolation threshold the slow part of a run from rest is the pressure field settling
// along the barely connected cluster (a diffusion over the whole box), and the coarse lattice
// has already found it.
#include "lbm/flow_solver.hpp"

#include <array>
#include <vector>

namespace cmp::flowrun {

// A converged flow on the lattice of an image refined M times: fields on every node of the
// (voxels * M)^3 grid, x fastest, as FlowSolver::density_field / velocity_field give them
// (density 0 on the nodes that take no part in the flow), and the drive they were run with.
struct CoarseFlow {
  std::array<int, 3> voxels{0, 0, 0};
  int refine = 1;
  std::vector<double> density, velocity;
  lbm::FlowSettings settings;
};

// The start of the same image at refinement M with `settings`: at each fine node the coarse
// fields interpolated (trilinear over the coarse nodes that flow, at the fine node's centre;
// periodic across the flow axis, and along it for body-force driving), rescaled to the fine
// lattice's units: the density's departure from the linear ramp of the pressure drop by the
// ratio of the drops (or of force times length), the velocity by the ratio of kappa_lu grad p /
// nu (kappa in lattice units grows as M^2). A fine node with no coarse node that flows around it
// starts at rest. Throws std::invalid_argument when the fields do not match voxels * refine.
lbm::StartState prolonged_start(const CoarseFlow& coarse, int M, const lbm::FlowSettings& settings);

}  // namespace cmp::flowrun
