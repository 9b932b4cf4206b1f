#pragma once
// Rattlers: the bodies of a jammed packing that carry no load. Every body that cannot balance
// its contacts is removed, which may strip its partners below balance in turn, until none is
// left. What "cannot balance" means is the packing's own rule (a sphere: fewer than d + 1
// contacts; a budding cell: spheres/rattlers.hpp and cells2d/packing_analysis.hpp), written
// as a predicate; the removal itself is written once, here.
//
// A body owns `sites_per_body` contact sites (a sphere one, a budding cell its two lobes): site
// s belongs to body s / sites_per_body, and a contact joins two sites of different bodies.
// The rule must be monotone (fewer contacts never make a body stable), so the result does not
// depend on the order of removal.
#include <span>
#include <utility>
#include <vector>

namespace cmp::packing {

struct Rattlers {
  std::vector<char> rattler;  // per body: 1 for a rattler
  std::vector<int> live;      // per site: its contacts with non-rattlers (0 on a rattler's sites)
};

// unstable(std::span<const int> live_of_body_sites) -> bool: the body cannot carry load.
template <class Unstable>
Rattlers prune_rattlers(int bodies, int sites_per_body, const std::vector<std::pair<int, int>>& contacts,
                        Unstable unstable) {
  const std::size_t n = static_cast<std::size_t>(bodies), m = static_cast<std::size_t>(sites_per_body);
  Rattlers r{std::vector<char>(n, 0), std::vector<int>(n * m, 0)};
  std::vector<std::vector<int>> touching(n);  // per body: the other site of each of its contacts
  for (const auto& [a, b] : contacts) {
    ++r.live[static_cast<std::size_t>(a)], ++r.live[static_cast<std::size_t>(b)];
    touching[static_cast<std::size_t>(a) / m].push_back(b);
    touching[static_cast<std::size_t>(b) / m].push_back(a);
  }
  const auto sites_of = [&](std::size_t body) { return std::span<const int>(r.live).subspan(body * m, m); };
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < n; ++i)
    if (unstable(sites_of(i))) r.rattler[i] = 1, pending.push_back(i);
  while (!pending.empty()) {
    const std::size_t i = pending.back();
    pending.pop_back();
    for (int site : touching[i]) {
      const std::size_t j = static_cast<std::size_t>(site) / m;
      if (r.rattler[j]) continue;
      --r.live[static_cast<std::size_t>(site)];
      if (unstable(sites_of(j))) r.rattler[j] = 1, pending.push_back(j);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (r.rattler[i])
      for (std::size_t s = 0; s < m; ++s) r.live[i * m + s] = 0;
  return r;
}

}  // namespace cmp::packing
