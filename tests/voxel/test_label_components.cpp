#include "voxel/label_components.hpp"

#include "voxel_fixtures.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

using namespace cmp::voxel;
namespace fx = cmp::voxel::fixtures;

namespace {
int label(const std::vector<std::uint8_t>& img, std::array<int, 3> d, std::vector<std::int32_t>& out, int conn,
          std::array<bool, 3> periodic = {false, false, false}) {
  LabelOptions o;
  o.connectivity = static_cast<Connectivity>(conn);
  o.periodic = periodic;
  return label_components(img.data(), d, out, o);
}
}  // namespace

TEST_CASE("label_components agrees with a flood fill on random images", "[voxel][label]") {
  const std::array<std::array<int, 3>, 4> shapes{{{17, 13, 11}, {1, 20, 9}, {30, 1, 1}, {8, 9, 40}}};
  for (int conn : {6, 18, 26})
    for (std::array<bool, 3> periodic :
         {std::array<bool, 3>{false, false, false}, {false, true, true}, {true, false, false}, {true, true, true}})
      for (double p : {0.2, 0.35, 0.6})
        for (std::size_t s = 0; s < shapes.size(); ++s) {
          const auto d = shapes[s];
          const auto img = fx::random_image(d, p, 100 + s);
          std::vector<int> ref;
          const int nref = fx::flood_fill_labels(img, d, conn, periodic, ref);
          for (int threads : {1, 2, 3}) {
            omp_set_num_threads(threads);
            std::vector<std::int32_t> lab;
            const int n = label(img, d, lab, conn, periodic);
            INFO("conn " << conn << " periodic " << periodic[0] << periodic[1] << periodic[2] << " p " << p
                         << " shape " << s << " threads " << threads);
            REQUIRE(n == nref);
            // Numbered in memory order, as the flood fill (which starts components in that order).
            REQUIRE(lab == std::vector<std::int32_t>(ref.begin(), ref.end()));
          }
        }
  omp_set_num_threads(2);
}

TEST_CASE("label_components numbering does not depend on the thread count", "[voxel][label]") {
  const std::array<int, 3> d{64, 48, 57};
  const auto img = fx::random_image(d, 0.3116, 9);  // near the site percolation threshold: big tangled clusters
  std::vector<std::int32_t> one, many;
  omp_set_num_threads(1);
  const int n1 = label(img, d, one, 6, {false, true, true});
  for (int t : {2, 4, 7}) {
    omp_set_num_threads(t);
    REQUIRE(label(img, d, many, 6, {false, true, true}) == n1);
    REQUIRE(many == one);
  }
  omp_set_num_threads(2);
}

TEST_CASE("a cluster wrapping around the periodic y boundary is one cluster", "[voxel][label]") {
  // A U-shaped tube: it leaves the box at y = ny-1 and comes back at y = 0.
  const std::array<int, 3> d{6, 10, 4};
  std::vector<std::uint8_t> img(6 * 10 * 4, 0);
  auto at = [&](int x, int y, int z) -> std::uint8_t& { return img[x + 6 * (y + 10 * z)]; };
  for (int y = 0; y < 3; ++y) at(1, y, 1) = 1;   // piece touching y = 0
  for (int y = 7; y < 10; ++y) at(1, y, 1) = 1;  // piece touching y = ny-1
  at(4, 5, 2) = 1;                               // an isolated voxel
  std::vector<std::int32_t> lab;
  CHECK(label(img, d, lab, 6) == 3);
  CHECK(label(img, d, lab, 6, {false, true, false}) == 2);
  CHECK(lab[1 + 6 * (0 + 10 * 1)] == lab[1 + 6 * (9 + 10 * 1)]);
  CHECK(label(img, d, lab, 6, {true, false, true}) == 3);  // other axes do not join it
  // Across the boundary, diagonally: only 18/26-connectivity joins (1, 9, 1) and (2, 0, 1).
  for (int y = 0; y < 3; ++y) at(1, y, 1) = 0;
  at(2, 0, 1) = 1;
  CHECK(label(img, d, lab, 6, {false, true, false}) == 3);
  CHECK(label(img, d, lab, 18, {false, true, false}) == 2);
  CHECK(label(img, d, lab, 18, {false, false, false}) == 3);
  // Through an edge of the box (y and z both wrap): a 26- but not 18-neighbour.
  std::fill(img.begin(), img.end(), 0);
  at(2, 9, 3) = 1;
  at(3, 0, 0) = 1;
  CHECK(label(img, d, lab, 18, {true, true, true}) == 2);
  CHECK(label(img, d, lab, 26, {true, true, true}) == 1);
  CHECK(label(img, d, lab, 26, {true, true, false}) == 2);
}

TEST_CASE("label_components edge cases", "[voxel][label]") {
  std::vector<std::int32_t> lab;
  const std::vector<std::uint8_t> empty(27, 0), full(27, 1);
  CHECK(label(empty, {3, 3, 3}, lab, 6) == 0);
  CHECK(lab == std::vector<std::int32_t>(27, 0));
  CHECK(label(full, {3, 3, 3}, lab, 6) == 1);
  CHECK(lab == std::vector<std::int32_t>(27, 1));
  const std::vector<std::uint8_t> one{7};
  CHECK(label(one, {1, 1, 1}, lab, 26, {true, true, true}) == 1);
  CHECK_THROWS_AS(label(one, {0, 1, 1}, lab, 6), std::invalid_argument);
  CHECK(connectivity_from_name("18") == Connectivity::Edges18);
  CHECK_THROWS(connectivity_from_name("8"));
}
