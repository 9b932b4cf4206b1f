#include "spheres/rattlers.hpp"

#include "packing/rattlers.hpp"

namespace cmp::spheres {

std::vector<int> contact_counts(int n, const std::vector<Contact>& contacts) {
  std::vector<int> counts(static_cast<std::size_t>(n), 0);
  for (const auto& c : contacts) ++counts[c.i], ++counts[c.j];
  return counts;
}

std::vector<bool> find_rattlers(int n, const std::vector<Contact>& contacts, int min_contacts) {
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(contacts.size());
  for (const auto& c : contacts) pairs.emplace_back(c.i, c.j);
  const auto r = packing::prune_rattlers(n, 1, pairs, [&](std::span<const int> live) { return live[0] < min_contacts; });
  return {r.rattler.begin(), r.rattler.end()};
}

}  // namespace cmp::spheres
