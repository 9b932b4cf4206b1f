#pragma once
// The halo of one rank (lbm/flow_solver.hpp): the population slots of the ghost nodes (fluid
// nodes of the planes just outside the rank's slabs, owned by a neighbouring rank) that the
// rank's odd sweep reads and writes through its link table. With the AA pattern each such slot
// is read and written by one node per step, so two copies a step pair suffice:
//  - after an EVEN step, the owner's values (its nodes' post-collision populations, stored
//    in their own slots) go to the ghost slots, which the next odd step gathers from;
//  - after an ODD step, the ghost slots (written by this rank's odd sweep) go back to the
//    owner, whose next even step reads them as its own.
// The boundary passes (pressure planes, interpolated walls) never write a halo slot (every
// halo slot belongs to a fluid link), so exchanging before them keeps every bit of the
// single-process run. One message per neighbour and direction, non-blocking.
#include "lbm/communicator.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace cmp::lbm {

// A ghost slot: the population slot q of the node at grid site `site`, owned by rank `owner`,
// stored here in slot `slot`.
struct GhostSlot {
  int owner;
  long site;
  int q;
  std::uint32_t slot;
};

class HaloExchange {
 public:
  // Collective over the ranks: sends each owner the list of its slots this rank holds, and
  // learns the same from the ranks holding this rank's slots (the relation is symmetric: links
  // are). `own_slot(site, q)` is this rank's slot of one of its own nodes.
  void build(const Communicator& comm, std::vector<GhostSlot> ghosts,
             const std::function<std::uint32_t(long site, int q)>& own_slot);
  template <class Real>
  void fill_ghosts(Real* F) const;  // after an even step
  template <class Real>
  void return_ghosts(Real* F) const;  // after an odd step
  bool empty() const { return peers_.empty(); }
  // Slots sent per step by this rank (average over an even and an odd step).
  double slots_per_step() const;

 private:
  struct Peer {
    int rank;
    std::vector<std::uint32_t> ghost;  // this rank's copies of the peer's slots
    std::vector<std::uint32_t> owned;  // this rank's slots the peer holds copies of (its order)
    mutable std::vector<char> out, in;
  };
  template <class Real>
  void transfer(Real* F, bool to_ghosts) const;
  const Communicator* comm_ = nullptr;
  std::vector<Peer> peers_;
};

}  // namespace cmp::lbm
