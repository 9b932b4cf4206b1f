#include "spheres/rattlers.hpp"

#include <catch2/catch.hpp>

using namespace cmp::spheres;

namespace {
std::vector<Contact> pairs(std::initializer_list<std::pair<int, int>> list) {
  std::vector<Contact> c;
  for (auto [i, j] : list) {
    Contact k;
    k.i = i, k.j = j;
    c.push_back(k);
  }
  return c;
}
}  // namespace

TEST_CASE("Rattlers: spheres with fewer than 4 contacts, removed iteratively") {
  // 0..4: a complete graph K5 (4 contacts each). 5 touches 0, 1, 2 (3 contacts: rattler).
  // 6 touches 0, 1, 2 and 7; 7 touches only 6: removing 7 leaves 6 with 3 -> rattler too.
  auto c = pairs({{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4},
                  {0, 5}, {1, 5}, {2, 5}, {0, 6}, {1, 6}, {2, 6}, {6, 7}});
  const auto r = find_rattlers(9, c);
  CHECK(r == std::vector<bool>{false, false, false, false, false, true, true, true, true});  // 8: no contact
  const auto counts = contact_counts(9, c);
  CHECK(counts[0] == 6);
  CHECK(counts[8] == 0);
  // The cascade: a chain hanging off K5 disappears link by link, K5 stays.
  const auto none = find_rattlers(5, pairs({{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
  CHECK(none == std::vector<bool>(5, false));
  // With min 5 contacts the whole K5 is rattlers.
  const auto all = find_rattlers(5, pairs({{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}), 5);
  CHECK(all == std::vector<bool>(5, true));
}
