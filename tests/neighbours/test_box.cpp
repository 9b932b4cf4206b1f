#include "neighbours/box.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::neighbours;

TEST_CASE("Box::minimum_image folds periodic axes into -L/2 .. L/2, leaves the others", "[neighbours][box]") {
  Box box;
  box.lower << -1, 0, 5;
  box.lengths << 4, 10, 2;
  box.periodic = {true, false, true};
  CHECK(box.minimum_image(Eigen::Vector3d(1.5, 7, 0.5)) == Eigen::Vector3d(1.5, 7, 0.5));
  CHECK(box.minimum_image(Eigen::Vector3d(2.5, -7, 1.5)) == Eigen::Vector3d(-1.5, -7, -0.5));
  CHECK(box.minimum_image(Eigen::Vector3d(-3.25, 0, -1.75)) == Eigen::Vector3d(0.75, 0, 0.25));
  CHECK(box.minimum_image(Eigen::Vector3d(4 * 7 + 0.5, 0, -2 * 11 - 0.25)) == Eigen::Vector3d(0.5, 0, -0.25));  // many periods
}

TEST_CASE("Box::wrap moves points into lower .. lower + L along periodic axes", "[neighbours][box]") {
  Box box;
  box.lower << -1, 0, 5;
  box.lengths << 4, 10, 2;
  box.periodic = {true, false, true};
  CHECK(box.wrap(Eigen::Vector3d(3.5, -20, 4)) == Eigen::Vector3d(-0.5, -20, 6));
  CHECK(box.wrap(Eigen::Vector3d(3, 0, 7)) == Eigen::Vector3d(-1, 0, 5));  // the upper face is the lower one
  CHECK(box.wrap(Eigen::Vector3d(-1, 0, 5)) == Eigen::Vector3d(-1, 0, 5));
  // one ulp below the lower face: s - floor(s) rounds to 1, which must not give lower + L
  const Eigen::Vector3d tiny = box.wrap(Eigen::Vector3d(std::nextafter(-1.0, -2.0), 0, std::nextafter(5.0, 0.0)));
  CHECK(tiny[0] >= -1);
  CHECK(tiny[0] < 3);
  CHECK(tiny[2] >= 5);
  CHECK(tiny[2] < 7);
}

TEST_CASE("make_planar_box: a zero-height box, periodic in x and y as asked", "[neighbours][box]") {
  const Box box = make_planar_box(Eigen::Vector2d(1, 2), Eigen::Vector2d(3, 4), true, false);
  CHECK(box.lower == Eigen::Vector3d(1, 2, 0));
  CHECK(box.lengths == Eigen::Vector3d(3, 4, 0));
  CHECK(box.periodic == std::array<bool, 3>{true, false, false});
  CHECK(box.minimum_image(Eigen::Vector3d(2, 3, 0)) == Eigen::Vector3d(-1, 3, 0));
}
