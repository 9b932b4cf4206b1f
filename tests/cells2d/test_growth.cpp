// Growth and division of one cell, and the jamming protocol on a small box.
#include "cells2d/colony.hpp"
#include "cells2d/growth.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace cmp;
using namespace cmp::cells2d;

TEST_CASE("cells2d growth: one cell grows exponentially by its bud and divides when the bud reaches sigma") {
  Random rng(3);
  std::vector<Cell> cells(1);
  cells[0].x = 2, cells[0].y = 3, cells[0].theta = 0.4, cells[0].rate = 1.0;
  const double a0 = cell_area(0);
  // Area doubles (pi/4 -> pi/2) after ln 2 / gamma: just before, one cell with a bud < sigma.
  const double dt = 1e-3;
  int steps = 0, divisions = 0;
  while (divisions == 0) {
    const double before = total_area(cells);
    divisions = grow_cells(cells, dt, rng, 0.1);
    ++steps;
    const double after = total_area(cells);
    CHECK(after == Approx(before * std::exp(dt)).epsilon(1e-12));  // area conserved across division
    if (divisions == 0) {
      CHECK(cells.size() == 1);
      CHECK(cells[0].bud < 1);
      CHECK(cells[0].x == 2);  // the centre of mass stays put while the bud grows
    }
  }
  CHECK(steps * dt == Approx(std::log(2.0)).margin(dt));
  REQUIRE(cells.size() == 2);
  // Daughters sit at the old lobe centres (centre of mass +- e/2), tiny buds, fresh rates.
  const Eigen::Vector2d e(std::cos(0.4), std::sin(0.4));
  CHECK((lobe_centre(cells[0], 0) - (Eigen::Vector2d(2, 3) + 0.5 * e)).norm() < 1e-12);
  CHECK((lobe_centre(cells[1], 0) - (Eigen::Vector2d(2, 3) - 0.5 * e)).norm() < 1e-12);
  for (const Cell& c : cells) {
    CHECK(c.bud < 0.1);
    CHECK(c.rate0 >= 0.9);
    CHECK(c.rate0 < 1.1);
  }
  CHECK(cells[0].theta != cells[1].theta);  // random orientations
  CHECK(total_area(cells) == Approx(a0 * std::exp(steps * dt)).epsilon(1e-10));
}

TEST_CASE("cells2d growth: gamma^0 draws are uniform within +-10 %") {
  Random rng(5);
  double lo = 2, hi = 0, mean = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double r = draw_rate(rng, 0.1);
    lo = std::min(lo, r), hi = std::max(hi, r), mean += r / n;
  }
  CHECK(lo >= 0.9);
  CHECK(lo < 0.901);
  CHECK(hi < 1.1);
  CHECK(hi > 1.099);
  CHECK(mean == Approx(1).margin(0.002));
}

TEST_CASE("cells2d jamming: a small box jams inside the energy window, beyond it to phi_J + dphi") {
  GrowthParameters p;
  p.box = 4;
  Colony colony(p, 11);
  long steps = 0;
  colony.grow_to_jamming([&](const StepRecord&) { ++steps; });
  REQUIRE(colony.jammed());
  const PackingAnalysis a = colony.analyse();
  const double per_cell = a.energy / a.cells;
  CHECK(per_cell >= 1e-16);
  CHECK(per_cell <= 2e-16);
  CHECK(steps == colony.counters().accepted);
  CHECK(colony.phi_jamming() > 0.7);
  CHECK(colony.phi_jamming() < 0.92);
  CHECK(a.Z >= a.Z_iso - 1e-12);  // at least isostatic (thesis Fig. S3.2)
  const double before = a.pressure;
  colony.grow_beyond(0.01);
  CHECK(std::abs(colony.area_fraction() - colony.phi_jamming() - 0.01) <= 0.5e-8);
  CHECK(colony.analyse().pressure > 100 * before);
}

TEST_CASE("cells2d jamming: the same seed gives the same colony, a copy grows as the original") {
  GrowthParameters p;
  p.box = 3.5;
  Colony a(p, 2), b(p, 2);
  a.grow_to_jamming();
  b.grow_to_jamming();
  REQUIRE(a.cells().size() == b.cells().size());
  for (std::size_t i = 0; i < a.cells().size(); ++i) {
    CHECK(a.cells()[i].x == b.cells()[i].x);
    CHECK(a.cells()[i].theta == b.cells()[i].theta);
  }
  Colony c(a);
  a.grow_beyond(0.005);
  c.grow_beyond(0.005);
  CHECK(a.area_fraction() == c.area_fraction());
  CHECK(a.analyse().pressure == c.analyse().pressure);
}

TEST_CASE("cells2d jamming: doubling dt after acceptance reaches the same jamming window") {
  for (const double box : {4.0, 5.0}) {
    GrowthParameters p;
    p.box = box;
    p.reset_step = false;
    Colony colony(p, 5);
    colony.grow_to_jamming();
    const PackingAnalysis a = colony.analyse();
    CHECK(a.energy / a.cells >= 1e-16);
    CHECK(a.energy / a.cells <= 2e-16);
    CHECK(a.Z >= a.Z_iso - 1e-12);
  }
}
