// The cut of a lattice's slabs over MPI ranks (lbm/slab_decomposition.hpp): whole slabs, nearly
// equal fluid nodes per rank, every rank at least one slab, too many ranks refused.
#include "lbm/slab_decomposition.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

using namespace cmp::lbm;

namespace {
std::vector<long> held(const SlabDecomposition& d, const std::vector<long>& fluid) {
  std::vector<long> per_rank;
  for (int r = 0; r < d.ranks(); ++r)
    per_rank.push_back(std::accumulate(fluid.begin() + d.first_slab[r], fluid.begin() + d.first_slab[r + 1], 0L));
  return per_rank;
}
}  // namespace

TEST_CASE("slabs: 16 planes each, the last one shorter") {
  CHECK(slab_count(1) == 1);
  CHECK(slab_count(16) == 1);
  CHECK(slab_count(17) == 2);
  CHECK(slab_count(144) == 9);
}

TEST_CASE("slabs: a uniform lattice is cut into equal ranges") {
  const std::vector<long> fluid(12, 100);
  const auto d = decompose_slabs(fluid, 4);
  CHECK(d.first_slab == std::vector<int>{0, 3, 6, 9, 12});
  CHECK(d.owner(0) == 0);
  CHECK(d.owner(5) == 1);
  CHECK(d.owner(11) == 3);
}

TEST_CASE("slabs: an uneven medium is cut by fluid nodes, not by planes") {
  // Dense slabs first, sparse later: the first rank takes fewer slabs.
  const std::vector<long> fluid{400, 400, 100, 100, 100, 100, 100, 100, 100, 100};
  const auto d = decompose_slabs(fluid, 2);
  CHECK(d.first_slab == std::vector<int>{0, 2, 10});
  const auto h = held(d, fluid);
  CHECK(h[0] == 800);
  CHECK(h[1] == 800);
}

TEST_CASE("slabs: every rank holds at least one slab, the ranges cover all slabs in order") {
  const std::vector<long> fluid{1000, 1, 1, 1, 1};
  for (int ranks = 1; ranks <= 5; ++ranks) {
    const auto d = decompose_slabs(fluid, ranks);
    REQUIRE(d.ranks() == ranks);
    CHECK(d.first_slab.front() == 0);
    CHECK(d.first_slab.back() == 5);
    for (int r = 0; r < ranks; ++r) CHECK(d.first_slab[r + 1] > d.first_slab[r]);
  }
}

TEST_CASE("slabs: the largest imbalance is one slab's fluid") {
  std::vector<long> fluid;
  for (int k = 0; k < 40; ++k) fluid.push_back(50 + (k * 37) % 91);  // uneven, deterministic
  const long total = std::accumulate(fluid.begin(), fluid.end(), 0L);
  const long largest = *std::max_element(fluid.begin(), fluid.end());
  for (int ranks : {2, 3, 4, 7}) {
    const auto h = held(decompose_slabs(fluid, ranks), fluid);
    for (long n : h) CHECK(std::abs(n - total / ranks) <= largest);
  }
}

TEST_CASE("slabs: more ranks than slabs is refused, naming both") {
  const std::vector<long> fluid(3, 10);
  CHECK_THROWS_MATCHES(decompose_slabs(fluid, 4), cmp::UsageError,
                       Catch::Matchers::Message("4 ranks but only 3 slabs of 16 planes along the flow axis: run on at "
                                                "most 3 ranks"));
}
