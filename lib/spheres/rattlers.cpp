#include "spheres/rattlers.hpp"

namespace cmp::spheres {

std::vector<int> contact_counts(int n, const std::vector<Contact>& contacts) {
  std::vector<int> counts(static_cast<std::size_t>(n), 0);
  for (const auto& c : contacts) ++counts[c.i], ++counts[c.j];
  return counts;
}

std::vector<bool> find_rattlers(int n, const std::vector<Contact>& contacts, int min_contacts) {
  std::vector<int> counts = contact_counts(n, contacts);
  std::vector<std::vector<int>> partners(static_cast<std::size_t>(n));
  for (const auto& c : contacts) partners[c.i].push_back(c.j), partners[c.j].push_back(c.i);
  std::vector<bool> rattler(static_cast<std::size_t>(n), false);
  std::vector<int> pending;
  for (int i = 0; i < n; ++i)
    if (counts[i] < min_contacts) rattler[i] = true, pending.push_back(i);
  while (!pending.empty()) {
    const int i = pending.back();
    pending.pop_back();
    for (int j : partners[i])
      if (!rattler[j] && --counts[j] < min_contacts) rattler[j] = true, pending.push_back(j);
  }
  return rattler;
}

}  // namespace cmp::spheres
