// The chamber of Chapter 2: relaxation to force balance, the outlet, the integrators' agreement
// as dt -> 0, the sticky law, bookkeeping and determinism. The walls' forces against their
// energy are checked by the generic harness (tests/forcefield, kind cells2d-chamber).
#include "cells2d/chamber.hpp"
#include "cells2d/avalanches.hpp"
#include "cells2d/chamber_output.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace cmp;
using namespace cmp::cells2d;

namespace {

Cell cell_at(double x, double y, double theta, double bud, double rate = 1) {
  Cell c;
  c.x = x, c.y = y, c.theta = theta, c.bud = bud, c.rate0 = c.rate = rate;
  return c;
}

double max_force(ChamberRun& run) {
  std::vector<double> f;
  run.forces(f);
  double worst = 0;
  for (double v : f) worst = std::max(worst, std::abs(v));
  return worst;
}

// Nine cells on a grid closer than a diameter, some against the walls: every one overlaps.
std::vector<Cell> crowded(const ChamberGeometry& g) {
  std::vector<Cell> cells;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      cells.push_back(cell_at(0.3 + 0.75 * i, g.height - 0.3 - 0.7 * j, 0.7 * (i + 3 * j), 0.2 + 0.08 * (i + j)));
  return cells;
}

}  // namespace

TEST_CASE("chamber: without growth an overlapping configuration relaxes to zero force", "[chamber]") {
  for (const char* integrator : {"gear3", "euler", "rkc"}) {
    ChamberParameters p;
    p.geometry.width = 4, p.geometry.height = 4;
    p.grow = false, p.mobility = 1e3, p.integrator = integrator;
    ChamberRun run(p, 1, crowded(p.geometry));
    INFO(integrator);
    const double before = max_force(run);
    CHECK(before > 0.1);
    run.advance_to(2.0);  // 2,000 relaxation times 1/(mu k)
    CHECK(max_force(run) < 1e-9 * before);
    CHECK(run.cells().size() == 9);
    CHECK(run.left() == 0);
  }
}

TEST_CASE("chamber: a cell in the outlet channel stays until the growing colony behind pushes it out", "[chamber]") {
  ChamberParameters p;
  p.geometry.width = 4, p.geometry.height = 3, p.geometry.outlet = 1.4, p.geometry.channel = 2;
  p.mobility = 1e3, p.rate_spread = 0;
  std::vector<Cell> cells = {cell_at(2, -1.0, 1.5707963, 0, 0)};  // in the channel, not growing
  for (int i = 0; i < 3; ++i) cells.push_back(cell_at(1 + i, 2.2, 0.3 * i, 0.5));
  ChamberRun run(p, 3, cells);
  run.advance_to(0.5);
  // Untouched, it has not moved.
  REQUIRE(run.left() == 0);
  CHECK(run.cells()[0].y == -1.0);
  double exit_time = -1;
  while (run.time() < 8 && exit_time < 0) {
    run.advance_to(run.time() + 0.05);
    if (run.left() > 0) exit_time = run.time();
  }
  INFO("the first cell left at t = " << exit_time << " with " << run.cells().size() << " cells");
  REQUIRE(exit_time > 0);
  // The one that left is the channel's cell: the colony's cells are all still above it.
  bool still_there = false;
  for (const Cell& c : run.cells()) still_there |= c.rate0 == 0;
  CHECK_FALSE(still_there);
  // Cells are conserved: the initial four, one more per division, one less per exit.
  CHECK(static_cast<long>(run.cells().size()) == 4 + run.divisions() - run.left());
}

TEST_CASE("chamber: Gear, Euler and Runge-Kutta-Chebyshev converge to the same trajectory as dt -> 0", "[chamber]") {
  ChamberParameters p;
  p.geometry.width = 4, p.geometry.height = 4;
  p.mobility = 100;  // relaxation time 0.01 / gamma0: the run spans a few of them while cells grow
  const std::vector<Cell> start = crowded(p.geometry);
  const auto final_state = [&](const char* integrator, double dt) {
    ChamberParameters q = p;
    q.integrator = integrator, q.dt = dt;
    ChamberRun run(q, 5, start);
    run.advance_to(0.04);
    REQUIRE(run.divisions() == 0);
    std::vector<double> x;
    for (const Cell& c : run.cells()) x.insert(x.end(), {c.x, c.y, c.theta, c.bud});
    return x;
  };
  const auto distance = [](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  };
  const std::vector<double> reference = final_state("gear4", 1e-6);
  for (const char* integrator : {"euler", "gear3", "rkc"}) {
    std::vector<double> errors;
    for (double dt : {4e-4, 2e-4, 1e-4, 5e-5}) errors.push_back(distance(final_state(integrator, dt), reference));
    WARN(integrator << " max error at dt 4e-4 ... 5e-5: " << errors[0] << " " << errors[1] << " " << errors[2] << " "
                    << errors[3]);
    INFO(integrator << " errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3]);
    // Halving dt halves Euler's and RKC's error (first order) and quarters Gear's (second order
    // globally).
    const bool euler = std::string(integrator) != "gear3";
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double ratio = errors[k] / errors[k - 1];
      if (euler)
        CHECK((ratio > 0.4 && ratio < 0.6));
      else
        CHECK(ratio < 0.3);
    }
    CHECK(errors.back() < (euler ? 3e-3 : 2e-5));
  }
  // At a step 250 times smaller they agree to Euler's error there (~8e-6).
  CHECK(distance(final_state("euler", 2e-7), final_state("gear3", 2e-7)) < 2e-5);
}

TEST_CASE("chamber: a lobe pushed past a corner of the chamber is pushed back by both walls", "[chamber]") {
  ChamberGeometry g;
  g.width = 4, g.height = 5;
  ChamberWalls walls(g, contact_law("harmonic"));
  // Bud-less cells whose centres lie beyond both walls of each corner (outside both spans).
  const std::vector<std::pair<double, double>> beyond = {{-0.2, 5.3}, {4.3, 5.2}, {4.2, -0.3}, {-0.25, -0.2}};
  for (const auto& [x, y] : beyond) {
    std::vector<double> f(3, 0.0);
    walls.add_forces({cell_at(x, y, 0, 0)}, f.data());
    INFO("cell at " << x << ", " << y);
    CHECK(f[0] * (x < 0 ? 1 : -1) == Approx(0.5 + std::abs(x < 0 ? x : x - 4)));
    CHECK(f[1] * (y < 0 ? 1 : -1) == Approx(0.5 + std::abs(y < 0 ? y : y - 5)));
  }
}

TEST_CASE("chamber: the sticky law pulls cells within Delta into contact, the harmonic law does not", "[chamber]") {
  for (double attraction : {0.0, 0.1}) {
    ChamberParameters p;
    p.geometry.width = 6, p.geometry.height = 6;
    p.grow = false, p.mobility = 1e3, p.contact = "sticky", p.attraction = attraction;
    // Two bud-less cells 0.05 sigma apart, far from the walls.
    ChamberRun run(p, 1, {cell_at(2.5, 3, 0, 0), cell_at(3.55, 3, 0, 0)});
    run.advance_to(0.5);
    const double gap = std::abs(run.cells()[1].x - run.cells()[0].x) - 1;
    INFO("attraction " << attraction << " gap " << gap);
    if (attraction > 0)
      CHECK(std::abs(gap) < 1e-9);  // the well's minimum is at contact (delta = 0)
    else
      CHECK(gap == Approx(0.05).margin(1e-12));
  }
}

TEST_CASE("chamber: the same seed gives the same run, another seed another", "[chamber]") {
  ChamberParameters p;
  p.geometry.width = 4, p.geometry.height = 5;
  p.mobility = 500;
  const auto series = [&](std::uint64_t seed) {
    ChamberRun run(p, seed);
    std::vector<std::vector<std::string>> rows;
    for (int k = 1; k <= 40; ++k) {
      run.advance_to(0.1 * k);
      rows.push_back(chamber_row(run.sample()));
    }
    return rows;
  };
  const auto a = series(7);
  CHECK(a == series(7));
  CHECK(a != series(8));
  // By t = 4 the chamber (20 sigma^2) is full and cells have left through the outlet.
  CHECK(std::stol(a.back()[4]) > 0);
}

TEST_CASE("chamber: bad parameters are refused, naming the option", "[chamber]") {
  const auto problems_of = [](auto change) {
    ChamberParameters p;
    change(p);
    std::string all;
    for (const auto& [flag, message] : p.problems()) all += flag + ": " + message + "\n";
    return all;
  };
  CHECK(problems_of([](ChamberParameters&) {}).empty());
  CHECK_THAT(problems_of([](ChamberParameters& p) { p.geometry.outlet = 6; }), Catch::Contains("--outlet"));
  CHECK_THAT(problems_of([](ChamberParameters& p) { p.geometry.width = -1; }), Catch::Contains("--width"));
  CHECK_THAT(problems_of([](ChamberParameters& p) { p.mobility = 0; }), Catch::Contains("--mobility"));
  CHECK_THAT(problems_of([](ChamberParameters& p) { p.dt = 1e-3; }), Catch::Contains("--dt"));  // 80 mu k: unstable
  CHECK_THAT(problems_of([](ChamberParameters& p) { p.integrator = "rk4"; }), Catch::Contains("unknown integrator"));
  // Every problem at once.
  const std::string many = problems_of([](ChamberParameters& p) {
    p.geometry.height = 0, p.mobility = -1, p.P0 = -1;
  });
  CHECK_THAT(many, Catch::Contains("--height") && Catch::Contains("--mobility") && Catch::Contains("--P0"));
}

TEST_CASE("avalanches: a sawtooth series gives its drops, rates and sizes", "[chamber]") {
  // Five cycles sampled every 0.05: the pressure rises from 0.1 to 0.3 over 0.9, then falls back
  // to 0.1 over 0.1 while three cells leave.
  PressureSeries s;
  long left = 0;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.05 * k, phase = std::fmod(t, 1.0);
    const bool falling = phase > 0.9 + 1e-9;
    s.time.push_back(t);
    s.pressure.push_back(falling ? 0.3 - 2 * (phase - 0.9) : 0.1 + 0.2 * phase / 0.9);
    if (falling) left += 3;
    s.left.push_back(left);
  }
  const auto events = find_avalanches(s, 0.06, 0);
  REQUIRE(events.size() == 5);
  for (std::size_t e = 0; e < events.size(); ++e) {
    INFO("event " << e);
    CHECK(events[e].peak == Approx(0.3).margin(1e-9));
    CHECK(events[e].drop == Approx(0.2).margin(1e-9));
    CHECK(events[e].drop_rate == Approx(0.2 / 0.1).epsilon(1e-9));
    CHECK(events[e].size == 3);
    if (e > 0) CHECK(events[e].rise_rate == Approx(0.2 / 0.9).epsilon(0.1));
  }
  const AvalancheSummary m = summarise(s, events, 0);
  CHECK(m.events == 5);
  CHECK(m.rate_ratio > 5);  // drops far faster than rises
  CHECK(m.mean_pressure == Approx(0.2).margin(0.01));
}
