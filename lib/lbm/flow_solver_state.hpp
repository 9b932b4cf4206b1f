#pragma once
// The state behind FlowSolver (internal to lib/lbm) and the parts that build and advance it,
// one file each:
//   lbm/link_table.cpp          numbering of the fluid nodes, link table, pressure-plane nodes
//   lbm/interpolated_walls.cpp  Bouzidi wall links: built from the wall fractions, applied after each step
//   lbm/pressure_planes.cpp     Zou-He pressure nodes, applied after each step
//   lbm/flow_step.cpp           one AA step: the sweep over the node chunks, then the boundary passes
//   lbm/flow_observables.cpp    macroscopic observables and fields
//   lbm/flow_checkpoint.cpp     fingerprint, checkpoint save and load
//   lbm/flow_solver.cpp         settings checks, construction order, initial state
#include "lbm/flow_solver.hpp"

#include "lbm/communicator.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/halo_exchange.hpp"
#include "lbm/huge_pages.hpp"
#include "lbm/layout.hpp"
#include "lbm/slab_decomposition.hpp"

#include "core/fixed_chunks.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace cmp::lbm {

// An interpolated (Bouzidi) wall link, applied after each step:
// F[target] = k[0] F[target] + k[1] F[first[parity]] + k[2] F[second[parity]].
struct WallLink {
  std::uint32_t target;
  std::uint32_t first[2], second[2];  // [0]: after an even step, [1]: after an odd step
  double k[3];
};

// A wall link whose wall is not half-way along it (fraction in fluid != 1/2), found while
// building the link table; interpolated_walls.cpp turns it into a WallLink.
struct WallFraction {
  long node;
  int q;
  double fraction;
};

// A fluid node on the inlet or outlet plane (Zou-He pressure node).
struct PressureNode {
  long node;
  int sign;    // +1: inlet (the inward normal is +axis), -1: outlet
  double rho;  // imposed density
};

struct FlowSolver::Impl {
  FlowSettings settings;
  int n[3] = {0, 0, 0};
  // This rank's own fluid nodes are [0, fluid) (the sweep covers [0, stride)); its ghost nodes
  // (lbm/halo_exchange.hpp) are [stride, ghost_end). One process: no ghosts, ghost_end = stride.
  long fluid = 0, stride = 0, ghost_end = 0, steps = 0;
  std::vector<long> site;              // own fluid node -> grid index
  std::vector<long> ghost_site;        // ghost node stride + k -> grid index
  // The decomposition (lbm/slab_decomposition.hpp): this rank's slabs [first_slab, first_slab +
  // slab_start.size() - 1), slab k's own nodes [slab_start[k - first_slab], slab_start[k - first_slab + 1]);
  // own node i is node first_node + i of the whole lattice's numbering (global_fluid nodes).
  Communicator comm;
  SlabDecomposition decomposition;
  int first_slab = 0;
  std::vector<long> slab_start;
  long first_node = 0, global_fluid = 0;
  HaloExchange halo;
  double halo_seconds = 0;  // wall time in the halo exchange (waiting for the neighbours included)
  // Between build_link_table and the halo's construction only.
  std::vector<GhostSlot> pending_ghosts;
  std::function<std::uint32_t(long site, int q)> own_slot;
  BigVector<std::uint32_t> links;     // 18 * ghost_end
  std::vector<std::uint32_t> consecutive;  // per block: consecutive_lines() (empty when no chunk uses it)
  std::vector<char> chunk_consecutive;     // per chunk: whether its odd sweeps use `consecutive`
  BigVector<double> fd;                // populations (double storage)
  BigVector<float> ff;                 // populations (float storage)
  std::vector<PressureNode> open;
  std::vector<WallLink> walls;
  long wall_links = 0;
  std::unique_ptr<CollisionOperator> op;
  double force[3] = {0, 0, 0};
  double nu = 0, grad_p = 0;
  int chunks = 1;
  std::uint64_t fp = 0;

  long chunk_start(int c) const { return chunk_begin(stride, chunks, c, kBatch); }

  template <class Real>
  BigVector<Real>& pops();

  // Slot holding the population arriving at `node` along q for the next step, after a step of
  // parity `after_odd` (AA pattern: the slot moves with the parity).
  std::size_t incoming_slot(int q, long node, bool after_odd) const {
    if (q == 0) return pop_slot(0, node);
    return after_odd ? pop_slot(q, node) : links[link_index(opposite(q), node)];
  }

  // link_table.cpp: cuts the slabs over the ranks, numbers this rank's fluid nodes and ghost
  // nodes (site, ghost_site, fluid, stride, ghost_end, chunks), fills the link table, the
  // pressure-plane nodes, wall_links, the consecutive lines, and the ghost slots the halo is
  // built from (pending_ghosts, own_slot: flow_solver.cpp); returns the wall links that need
  // interpolation.
  std::vector<WallFraction> build_link_table(const PoreLattice& lattice);
  // interpolated_walls.cpp
  void build_walls(const std::vector<WallFraction>& fractions);
  template <class Real>
  void apply_walls(Real* F, bool after_odd) const;
  // pressure_planes.cpp
  template <class Real>
  void apply_pressure_planes(Real* F, bool after_odd) const;
  template <int A, class Real>
  void pressure_nodes(Real* F, long begin, long end, bool after_odd) const;
  // flow_solver.cpp: the density of the start at rest (the linear ramp of the pressure drop);
  // every slot at the equilibrium of a state
  double rest_density(long grid_index) const;
  void fill_equilibrium(const StartState& state);
  // flow_step.cpp
  template <class Real>
  void step_once();
  // flow_observables.cpp
  template <class Real>
  void gather(const BigVector<Real>& F, long node, double f[kQ]) const;
  template <class Real>
  FlowObservables observe() const;
  std::vector<double> field_records() const;  // collective: on rank 0 all ranks' (site, u, rho)
  // flow_checkpoint.cpp
  std::uint64_t fingerprint_of(const PoreLattice& lattice) const;
};

template <>
inline BigVector<double>& FlowSolver::Impl::pops<double>() { return fd; }
template <>
inline BigVector<float>& FlowSolver::Impl::pops<float>() { return ff; }

}  // namespace cmp::lbm
