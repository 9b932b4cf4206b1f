// lib/packing/rattlers.hpp: the one removal of rattlers, under a sphere's rule and a budding
// cell's two-lobe rule.
#include "packing/rattlers.hpp"

#include <catch2/catch.hpp>

using namespace cmp::packing;

namespace {
bool fewer_than_2(std::span<const int> live) { return live[0] < 2; }
}  // namespace

TEST_CASE("prune_rattlers removes in cascade and keeps a stable ring", "[packing][rattlers]") {
  // A ring 0-1-2-3-0 (each body 2 contacts) with a tail 3-4-5: 5 has 1 contact, then 4 has 1.
  const std::vector<std::pair<int, int>> c{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {3, 4}, {4, 5}};
  const auto r = prune_rattlers(6, 1, c, fewer_than_2);
  CHECK(r.rattler == std::vector<char>{0, 0, 0, 0, 1, 1});
  CHECK(r.live == std::vector<int>{2, 2, 2, 2, 0, 0});  // 3 lost its contact with the tail
  // Cut the ring once: everything unravels.
  const auto open = prune_rattlers(6, 1, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}}, fewer_than_2);
  CHECK(open.rattler == std::vector<char>(6, 1));
}

TEST_CASE("prune_rattlers over two sites per body counts each lobe apart", "[packing][rattlers]") {
  // Four budding cells, body b owning sites 2b and 2b + 1. Bodies 1-3 touch each other on their
  // first lobes (sites 2, 4, 6) and each touches body 0: every body has three contacts.
  const auto cell_rule = [](std::span<const int> live) {
    const int total = live[0] + live[1];
    return total < 3 || (total == 3 && live[0] > 0 && live[1] > 0);
  };
  const std::vector<std::pair<int, int>> triangle{{2, 4}, {2, 6}, {4, 6}};
  auto one_lobe = triangle;  // body 0 holds all three on site 0: it can balance them
  one_lobe.insert(one_lobe.end(), {{0, 2}, {0, 4}, {0, 6}});
  const auto stable = prune_rattlers(4, 2, one_lobe, cell_rule);
  CHECK(stable.rattler == std::vector<char>{0, 0, 0, 0});
  CHECK(stable.live == std::vector<int>{3, 0, 3, 0, 3, 0, 3, 0});
  auto split = triangle;  // 2 + 1 between body 0's lobes: it rattles, and takes the rest with it
  split.insert(split.end(), {{0, 2}, {0, 4}, {1, 6}});
  const auto pruned = prune_rattlers(4, 2, split, cell_rule);
  CHECK(pruned.rattler == std::vector<char>{1, 1, 1, 1});
  CHECK(pruned.live == std::vector<int>(8, 0));
}
