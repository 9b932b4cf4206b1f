// The halo exchange of lbm/halo_exchange.hpp.
#include "lbm/halo_exchange.hpp"

#include <algorithm>
#include <cstring>
#include <map>

namespace cmp::lbm {

namespace {
constexpr int kTagCounts = 101, kTagKeys = 102, kTagToGhosts = 103, kTagToOwners = 104;
}

void HaloExchange::build(const Communicator& comm, std::vector<GhostSlot> ghosts,
                         const std::function<std::uint32_t(long, int)>& own_slot) {
  comm_ = &comm;
  peers_.clear();
  std::sort(ghosts.begin(), ghosts.end(), [](const GhostSlot& a, const GhostSlot& b) {
    return a.owner != b.owner ? a.owner < b.owner : a.site != b.site ? a.site < b.site : a.q < b.q;
  });
  std::map<int, std::vector<long>> keys;  // per owner: (site, q) pairs, in the order above
  for (const GhostSlot& g : ghosts) {
    auto& k = keys[g.owner];
    k.push_back(g.site);
    k.push_back(g.q);
  }
  for (auto& [rank, k] : keys) {
    Peer p;
    p.rank = rank;
    for (const GhostSlot& g : ghosts)
      if (g.owner == rank) p.ghost.push_back(g.slot);
    peers_.push_back(std::move(p));
  }
  // The counts, then the keys, each way (the peers holding this rank's slots are the ones
  // whose slots it holds).
  std::vector<long> counts_out(peers_.size()), counts_in(peers_.size());
  std::vector<Communicator::Transfer> t;
  for (std::size_t i = 0; i < peers_.size(); ++i) {
    counts_out[i] = static_cast<long>(peers_[i].ghost.size());
    t.push_back({peers_[i].rank, &counts_out[i], sizeof(long), &counts_in[i], sizeof(long)});
  }
  comm.exchange(t, kTagCounts);
  std::vector<std::vector<long>> in(peers_.size());
  t.clear();
  for (std::size_t i = 0; i < peers_.size(); ++i) {
    const auto& k = keys[peers_[i].rank];
    in[i].resize(2 * static_cast<std::size_t>(counts_in[i]));
    t.push_back({peers_[i].rank, k.data(), k.size() * sizeof(long), in[i].data(), in[i].size() * sizeof(long)});
  }
  comm.exchange(t, kTagKeys);
  for (std::size_t i = 0; i < peers_.size(); ++i)
    for (std::size_t j = 0; j < in[i].size(); j += 2) peers_[i].owned.push_back(own_slot(in[i][j], static_cast<int>(in[i][j + 1])));
}

template <class Real>
void HaloExchange::transfer(Real* F, bool to_ghosts) const {
  if (peers_.empty()) return;
  std::vector<Communicator::Transfer> t;
  for (const Peer& p : peers_) {
    const auto& from = to_ghosts ? p.owned : p.ghost;
    const auto& into = to_ghosts ? p.ghost : p.owned;
    p.out.resize(from.size() * sizeof(Real));
    p.in.resize(into.size() * sizeof(Real));
    Real* o = reinterpret_cast<Real*>(p.out.data());
    for (std::size_t i = 0; i < from.size(); ++i) o[i] = F[from[i]];
    t.push_back({p.rank, p.out.data(), p.out.size(), p.in.data(), p.in.size()});
  }
  comm_->exchange(t, to_ghosts ? kTagToGhosts : kTagToOwners);
  for (const Peer& p : peers_) {
    const auto& into = to_ghosts ? p.ghost : p.owned;
    const Real* v = reinterpret_cast<const Real*>(p.in.data());
    for (std::size_t i = 0; i < into.size(); ++i) F[into[i]] = v[i];
  }
}

template <class Real>
void HaloExchange::fill_ghosts(Real* F) const {
  transfer(F, true);
}
template <class Real>
void HaloExchange::return_ghosts(Real* F) const {
  transfer(F, false);
}

double HaloExchange::slots_per_step() const {
  double n = 0;
  for (const Peer& p : peers_) n += 0.5 * static_cast<double>(p.owned.size() + p.ghost.size());
  return n;
}

template void HaloExchange::fill_ghosts<double>(double*) const;
template void HaloExchange::fill_ghosts<float>(float*) const;
template void HaloExchange::return_ghosts<double>(double*) const;
template void HaloExchange::return_ghosts<float>(float*) const;

}  // namespace cmp::lbm
