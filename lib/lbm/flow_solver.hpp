#pragma once
// D3Q19 lattice Boltzmann solver for Stokes flow through the pore space of a PoreLattice.
//
// Storage: populations of FLUID NODES ONLY (blocks of 8 nodes, 19 directions per block,
// lbm/layout.hpp), plus a link table: for fluid node n and direction q = 1..18 the slot that the population
// leaving n along c_q goes to, resolved at build time: slot (q, neighbour) when the
// neighbour n + c_q is fluid, slot (opposite(q), n) when it is solid (half-way bounce-back)
// or outside the box along the flow axis (pressure driving, below). Solid nodes cost
// nothing. Memory: 19 populations (8 bytes, or 4 with Precision::kFloat) + 18 links of 4
// bytes per fluid node, + 4 bytes per 8 nodes on lattices with many consecutive link lines
// (below) (bytes_per_fluid_node()).
//
// Time stepping: fused stream + collide in place, the AA pattern (Bailey et al. 2009): even
// steps read a node's own slots and write the post-collision populations back reversed;
// odd steps gather through the link table and scatter back through it (in the node chunks
// where at least a quarter of the link lines hold 8 consecutive slots, as on dense boxes, such
// lines move as one vector: lbm/layout.hpp consecutive_lines()). Every slot is read
// and written by one node per step, so one array suffices, nodes may run in any order on
// any thread, and results are bit-identical for any thread count. The hot loop works on
// batches of 8 nodes with no branches (but that per consecutive line) and no divisions (lbm/sweep_kernel.hpp). Walls with
// interpolated bounce-back and the pressure nodes are fixed up after each sweep, link by
// link and node by node, in a fixed order.
//
// Layout along the flow axis: fluid nodes are numbered brick by brick (lbm/layout.hpp: bricks
// of 16 planes along the flow axis, a few rows wide across it, so that an odd step's neighbours
// in the next plane are near in memory), and 16 planes are one contiguous node range. Threads
// take fixed chunks of that range (dynamic hand-out, lib/core/fixed_chunks.hpp). On several MPI
// ranks each rank owns a contiguous range of 16-plane slabs (lbm/slab_decomposition.hpp); the
// links that leave its range (the only ones to neighbouring planes) point into ghost nodes
// whose slots are exchanged after each step (lbm/halo_exchange.hpp), with no change to the
// kernel. Observables are summed slab by slab, the slabs' sums then added in slab order on
// every rank: the same bits on one process and on any number of ranks.
//
// Driving (FlowSettings::driving):
//  - kPressure: periodic along the two other axes; along the flow axis the box is open, with
//    Zou & He (1997) pressure nodes (the D3Q19 form of Hecht & Harting 2010) on the fluid
//    nodes of the FIRST and LAST planes, as the thesis's Palabos setup: the density is
//    imposed ON those planes (rho_in = 1 + drop/2 on plane 0, rho_out = 1 - drop/2 on plane
//    n-1), the populations arriving from outside the box are reconstructed from the known
//    ones (bounce-back of the non-equilibrium part, zero tangential velocity). The planes are
//    n - 1 apart, hence |grad p| = c_s^2 drop / (n - 1). Solid nodes on the first and last
//    planes stay bounce-back walls. (An anti-bounce-back condition, half a node outside,
//    was tried first: it drops the shear stress of the entering populations and overshot
//    Poiseuille permeability by 5-25 % on short channels.)
//  - kBodyForce: fully periodic box, a uniform force density g along the axis on the fluid
//    (Guo forcing), |grad p| := g (a body force is equivalent to that pressure gradient).
//
// Start: at rest on the linear density ramp of the pressure drop, or from a guess of the steady
// flow (start_from: the flow of a coarser lattice prolonged, flowrun/prolong.hpp).
//
// Observables (observe()): kappa_lu = nu <u_axis> / |grad p|, <u_axis> the superficial mean
// over the WHOLE box (solid nodes count as zero velocity), nu = (tau - 1/2)/3, rho_0 = 1.
#include "lbm/collision.hpp"
#include "lbm/communicator.hpp"
#include "lbm/pore_lattice.hpp"

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace cmp::lbm {

enum class Driving { kPressure, kBodyForce };
enum class Precision { kDouble, kFloat };  // storage of the populations (arithmetic is double;
                                            // float stores f - w_q, lbm/layout.hpp)

struct FlowSettings {
  std::string collision = "mrt";   // a collision_styles() name
  CollisionParameters collision_parameters;
  int axis = 0;                    // flow axis 0/1/2; the other two are periodic
  Driving driving = Driving::kPressure;
  double density_drop = 1e-3;      // pressure driving: rho_in - rho_out (lattice units), rho_in = 1 + drop/2
  double body_force = 1e-6;        // body-force driving: g along axis (lattice units), fully periodic
  Precision precision = Precision::kDouble;
};

struct FlowObservables {           // every field in lattice units
  long steps = 0;
  double kappa_lu = 0;             // nu * <u_axis>_box / |grad p|, superficial average over the whole box
  double tortuosity = 0;           // tau_H = sum |u| / sum u_axis over fluid nodes (Eq. S5.14)
  double superficial_velocity = 0; // sum u_axis / (nx ny nz)
  double interstitial_velocity = 0;// sum u_axis / fluid nodes
  double max_speed = 0;            // max |u| over fluid nodes
  double reynolds = 0;             // Re = superficial velocity * sqrt(kappa_lu) / nu (the Darcy-scale Reynolds number)
  double mach = 0;                 // Ma = max|u| / c_s
  double mass = 0;                 // sum of rho over fluid nodes
  double pressure_gradient = 0;    // the |grad p| used in kappa_lu (c_s^2 drop / (n - 1), or g)
};

// Memory traffic of one update of one fluid node, the bytes a bandwidth bound divides by: the
// 19 populations read and written once (the AA pattern works in place: no write-allocate) and
// the 18 four-byte links, read on odd steps only. Double: 2 x 19 x 8 + 18 x 4 / 2 = 340.
double update_bytes(Precision precision);

// The macroscopic state a run starts from at one node (its grid index, x fastest): density
// and velocity in lattice units.
using StartState = std::function<void(long grid_index, double& rho, double u[3])>;

class FlowSolver {
 public:
  // Builds the link table and starts from rest at the linear density profile of the
  // pressure drop (or rho = 1). Throws cmp::UsageError on bad settings (tau <= 1/2, unknown
  // collision, axis not 0..2, drop or force not finite, fewer than 2 planes along the axis,
  // a lattice of the wrong size, no fluid node, more than 2^32/19 nodes).
  FlowSolver(const PoreLattice& lattice, const FlowSettings& settings);
  // The same flow on the ranks of `comm` (lbm/communicator.hpp), each holding its slabs
  // (lbm/slab_decomposition.hpp) and their halo (lbm/halo_exchange.hpp): a collective call, as
  // are step(), observe(), the fields, save() and load(); every rank gets the same observables,
  // bit for bit those of one process. Throws cmp::UsageError when ranks exceed slabs.
  FlowSolver(const PoreLattice& lattice, const FlowSettings& settings, const Communicator& comm);
  ~FlowSolver();
  FlowSolver(FlowSolver&&) noexcept;
  FlowSolver& operator=(FlowSolver&&) noexcept;

  // Replaces the state by the equilibrium of `state` at every node (each rank asks for its own
  // nodes only), step count 0: a run started from a guess of the steady flow (the flow of a
  // coarser lattice, flowrun/prolong.hpp) instead of rest. Collective.
  void start_from(const StartState& state);
  // n fused stream+collide steps on all OpenMP threads, same bits for any thread count.
  void step(long n);
  // Macroscopic observables of the current state (ordered reductions: thread-independent).
  FlowObservables observe() const;
  long steps() const;
  long fluid_nodes() const;  // of the whole lattice (all ranks)
  // Population slots this rank sends per step to its neighbours (0 on one process), and the
  // wall seconds this rank spent in the halo exchange so far (waiting for slower ranks included).
  double halo_slots_per_step() const;
  double halo_seconds() const;
  // Storage per fluid node: populations + link table (+ interpolated-wall data, averaged); on
  // several ranks the storage of all ranks (halo included) over the lattice's fluid nodes.
  double bytes_per_fluid_node() const;
  // Memory traffic of one step per fluid node: update_bytes() over every node the sweep covers
  // (the last block's padding included), plus the per-block bits of lbm/layout.hpp's
  // consecutive lines, read on odd steps where a chunk uses them. The boundary passes
  // (pressure planes, interpolated walls) are not counted.
  double bytes_moved_per_update() const;
  // Links with interpolated (Bouzidi) bounce-back, and all solid wall links.
  long interpolated_links() const;
  const FlowSettings& settings() const;

  // Fields on the full nx*ny*nz grid (x fastest), for VTK output: velocity 3 values per node
  // interleaved (solid nodes 0), density (solid nodes 0). On several ranks: gathered on rank 0
  // (empty on the others).
  std::vector<double> velocity_field() const;
  std::vector<double> density_field() const;

  // Checkpoint: the complete state (populations, step count), fingerprint() and the
  // convergence checks made so far (`history`, so that a resumed run_to_steady_state decides
  // exactly as an uninterrupted one) in a binary stream. load() returns that history and
  // throws cmp::InputError(name, 0, why) if the stream is not a checkpoint, is truncated, or
  // its fingerprint differs (a resume file from another lattice or settings); the solver is
  // unchanged then.
  void save(std::ostream& out, const std::vector<FlowObservables>& history = {}) const;
  std::vector<FlowObservables> load(std::istream& in, const std::string& name = "checkpoint");
  // 64-bit FNV-1a hash of the lattice (sizes, fluid mask, wall fractions) and the settings.
  std::uint64_t fingerprint() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cmp::lbm
