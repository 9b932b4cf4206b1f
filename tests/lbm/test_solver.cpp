// FlowSolver as a program uses it: same bits on any thread count, checkpoints, storage
// precision, mass, the pressure profile, tortuosity, steady-state detection, bad settings.
#include "lbm/flow_solver.hpp"
#include "lbm/pore_lattice.hpp"
#include "lbm/sphere_lattice.hpp"
#include "lbm/steady_state.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <sstream>

using namespace cmp::lbm;

namespace {

// A small porous box: overlapping spheres in a periodic 20 x 16 x 16 lattice.
PoreLattice porous() {
  return periodic_spheres(20, 16, 16, {{4, 4, 4, 4.5}, {12, 10, 6, 5}, {7, 12, 13, 4}, {16, 3, 11, 3.5}, {2, 9, 9, 3}});
}

FlowSettings pressure_settings(const char* collision = "mrt") {
  FlowSettings s;
  s.collision = collision;
  s.density_drop = 1e-3;
  return s;
}

bool same_bits(const FlowObservables& a, const FlowObservables& b) {
  return a.steps == b.steps && std::memcmp(&a.kappa_lu, &b.kappa_lu, sizeof(double)) == 0 &&
         std::memcmp(&a.tortuosity, &b.tortuosity, sizeof(double)) == 0 && std::memcmp(&a.mass, &b.mass, sizeof(double)) == 0 &&
         std::memcmp(&a.max_speed, &b.max_speed, sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("solver: same bits on 1 and 2 threads") {
  for (Driving d : {Driving::kPressure, Driving::kBodyForce}) {
    FlowSettings s = pressure_settings();
    s.driving = d;
    PoreLattice p = porous();
    FlowObservables o[2];
    std::vector<double> u[2];
    for (int t = 1; t <= 2; ++t) {
      omp_set_num_threads(t);
      FlowSolver solver(p, s);  // Bouzidi walls (wall_fraction set) included
      solver.step(301);
      o[t - 1] = solver.observe();
      u[t - 1] = solver.velocity_field();
    }
    omp_set_num_threads(2);
    CHECK(same_bits(o[0], o[1]));
    CHECK(std::memcmp(u[0].data(), u[1].data(), u[0].size() * sizeof(double)) == 0);
  }
}

TEST_CASE("solver: save and load mid-run, then continue, gives the bits of an uninterrupted run") {
  const PoreLattice p = porous();
  const FlowSettings s = pressure_settings();
  ConvergenceSettings c;
  c.tol = 1e-5;
  c.check_every = 50;
  c.window = 3;
  FlowSolver whole(p, s);
  const SteadyStateResult full = run_to_steady_state(whole, c);
  REQUIRE(full.converged);

  // Interrupted after 7 checks plus an odd number of steps (the AA parity is part of the state).
  FlowSolver first(p, s);
  c.max_steps = 350;
  const SteadyStateResult part = run_to_steady_state(first, c);
  REQUIRE_FALSE(part.converged);
  first.step(1);
  std::stringstream file;
  first.save(file, part.history);
  FlowSolver second(p, s);
  const std::vector<FlowObservables> history = second.load(file, "run.chk");
  CHECK(second.steps() == 351);
  CHECK(history.size() == part.history.size());
  CHECK(same_bits(second.observe(), first.observe()));
  // Continuing the steps: back on the check grid after 49 steps, then as the whole run.
  second.step(49);
  FlowSolver reference(p, s);
  reference.step(400);
  CHECK(same_bits(second.observe(), reference.observe()));
  c.max_steps = 200000;
  FlowSolver third(p, s);
  std::stringstream file2;
  FlowSolver at350(p, s);
  at350.step(350);
  at350.save(file2, part.history);
  const SteadyStateResult resumed = run_to_steady_state(third, c, {}, third.load(file2));
  CHECK(resumed.converged);
  CHECK(same_bits(resumed.final, full.final));
  CHECK(resumed.history.size() == full.history.size());
}

TEST_CASE("solver: a checkpoint of another run, or not a checkpoint, is refused") {
  const PoreLattice p = porous();
  FlowSolver a(p, pressure_settings());
  FlowSettings other = pressure_settings();
  other.collision_parameters.tau = 0.9;
  FlowSolver b(p, other);
  CHECK(a.fingerprint() != b.fingerprint());
  std::stringstream file;
  a.save(file);
  CHECK_THROWS_AS(b.load(file, "a.chk"), cmp::InputError);
  std::stringstream junk("not a checkpoint at all");
  CHECK_THROWS_AS(a.load(junk, "junk.chk"), cmp::InputError);
  std::stringstream whole;
  a.save(whole);
  std::stringstream truncated(whole.str().substr(0, whole.str().size() / 2));
  CHECK_THROWS_AS(a.load(truncated, "cut.chk"), cmp::InputError);
}

TEST_CASE("solver: float storage keeps kappa within 0.1 % of double") {
  // Float slots hold f - w_q (lbm/layout.hpp); storing f itself was 2 % off on the 8^3 image.
  struct Case {
    const char* name;
    PoreLattice lattice;
    Driving driving;
  };
  const Case cases[] = {
      {"Poiseuille, plane channel h = 10", channel(12, 10, 0, 1), Driving::kPressure},
      {"simple cubic sphere array, n = 16, solid fraction 0.2", simple_cubic_array(16, 0.2), Driving::kBodyForce},
      {"8^3 image, one sphere of radius 4.1 (porosity 0.45, narrow throats)", periodic_spheres(8, 8, 8, {{4, 4, 4, 4.1}}),
       Driving::kPressure},
      {"porous box", porous(), Driving::kPressure},
  };
  ConvergenceSettings c;
  c.tol = 1e-6;
  c.check_every = 100;  // lbflow's defaults
  c.window = 10;
  for (const Case& k : cases) {
    FlowSettings s = pressure_settings();
    s.driving = k.driving;
    s.body_force = 1e-5;
    FlowSolver d(k.lattice, s);
    const SteadyStateResult rd = run_to_steady_state(d, c);
    s.precision = Precision::kFloat;
    FlowSolver f(k.lattice, s);
    const SteadyStateResult rf = run_to_steady_state(f, c);
    INFO(k.name << ": double " << rd.final.kappa_lu << " (" << rd.final.steps << " steps), float " << rf.final.kappa_lu
                << " (" << rf.final.steps << " steps)");
    CHECK(rd.converged);
    CHECK(rf.converged);
    CHECK(std::abs(rf.final.kappa_lu / rd.final.kappa_lu - 1) < 1e-3);
    CHECK(f.bytes_per_fluid_node() < d.bytes_per_fluid_node() - 70);
  }
}

TEST_CASE("solver: the bytes a step moves per fluid node, as the bandwidth bound counts them") {
  // A dense 16^3 box: no padding, and its chunks read the consecutive-line bits (4 bytes per
  // block of 8 nodes, on odd steps); 19 populations read and written, 18 links of 4 bytes read
  // every other step.
  FlowSettings s = pressure_settings();
  s.driving = Driving::kBodyForce;
  s.body_force = 1e-5;
  FlowSolver d(open_box(16, 16, 16), s);
  CHECK(d.bytes_moved_per_update() == Approx(2 * 19 * 8 + 18 * 4 / 2 + 4.0 / 8 / 2).epsilon(1e-12));
  s.precision = Precision::kFloat;
  FlowSolver f(open_box(16, 16, 16), s);
  CHECK(f.bytes_moved_per_update() == Approx(2 * 19 * 4 + 18 * 4 / 2 + 4.0 / 8 / 2).epsilon(1e-12));
  // A porous lattice: the padding of the last block counts (and the bits, where a chunk uses them).
  s.precision = Precision::kDouble;
  s.driving = Driving::kPressure;
  FlowSolver p(porous(), s);
  const double nodes_swept = std::ceil(static_cast<double>(p.fluid_nodes()) / 8) * 8;
  const double populations_and_links = 340.0 * nodes_swept / static_cast<double>(p.fluid_nodes());
  CHECK(p.bytes_moved_per_update() >= populations_and_links - 1e-9);
  CHECK(p.bytes_moved_per_update() <= populations_and_links + 0.25 + 1e-9);
}

TEST_CASE("solver: mass is conserved in a periodic porous box") {
  FlowSettings s = pressure_settings();
  s.driving = Driving::kBodyForce;
  s.body_force = 1e-5;
  PoreLattice p = porous();
  p.wall_fraction = nullptr;  // interpolated walls do not conserve mass exactly
  FlowSolver solver(p, s);
  const double m0 = solver.observe().mass;
  CHECK(m0 == Approx(static_cast<double>(solver.fluid_nodes())).epsilon(1e-14));
  solver.step(500);
  CHECK(std::abs(solver.observe().mass / m0 - 1) < 1e-13);
}

TEST_CASE("solver: the pressure falls linearly along a uniform channel") {
  const PoreLattice p = channel(24, 6, 0, 1);
  FlowSolver solver(p, pressure_settings("trt"));
  ConvergenceSettings c;
  c.tol = 1e-9;
  c.check_every = 50;
  c.window = 4;
  REQUIRE(run_to_steady_state(solver, c).converged);
  const std::vector<double> rho = solver.density_field();
  const double drop = 1e-3;
  for (int x = 0; x < 24; ++x)
    for (int y = 1; y <= 6; ++y) {
      const double expected = 1 + drop / 2 - drop * x / 23.0;
      CHECK(std::abs(rho[static_cast<std::size_t>(p.index(x, y, 0))] - expected) < 1e-3 * drop);
    }
}

TEST_CASE("solver: tau_H is 1 in a straight channel and above 1 in a tortuous one") {
  FlowSettings s = pressure_settings();
  s.driving = Driving::kBodyForce;
  ConvergenceSettings c;
  c.tol = 1e-8;
  c.check_every = 50;
  c.window = 4;
  FlowSolver straight(channel(4, 8, 0, 1, true, 6), s);
  const FlowObservables o = run_to_steady_state(straight, c).final;
  CHECK(std::abs(o.tortuosity - 1) < 1e-12);
  // Staggered baffles: the flow zigzags around them.
  PoreLattice z = channel(24, 10, 0, 1);
  for (int x : {4, 16})
    for (int y = 1; y <= 7; ++y) z.fluid[static_cast<std::size_t>(z.index(x, y, 0))] = 0;
  for (int x : {10, 22})
    for (int y = 4; y <= 10; ++y) z.fluid[static_cast<std::size_t>(z.index(x, y, 0))] = 0;
  FlowSolver zigzag(z, s);
  const FlowObservables t = run_to_steady_state(zigzag, c).final;
  INFO("tau_H " << t.tortuosity);
  CHECK(t.tortuosity > 1.2);
}

TEST_CASE("solver: the step cap ends a run unconverged, with its history") {
  FlowSolver solver(porous(), pressure_settings());
  ConvergenceSettings c;
  c.tol = 1e-12;
  c.check_every = 20;
  c.max_steps = 100;
  int calls = 0;
  const SteadyStateResult r = run_to_steady_state(solver, c, [&](const FlowObservables&) { ++calls; });
  CHECK_FALSE(r.converged);
  CHECK(r.final.steps == 100);
  CHECK(calls == 5);
  CHECK(r.history.size() == 5);
}

TEST_CASE("solver: bad settings are refused with a usage error") {
  const PoreLattice p = porous();
  auto bad = [&](auto change) {
    FlowSettings s = pressure_settings();
    change(s);
    CHECK_THROWS_AS(FlowSolver(p, s), cmp::UsageError);
  };
  bad([](FlowSettings& s) { s.collision_parameters.tau = 0.5; });
  bad([](FlowSettings& s) { s.collision = "lbgk"; });
  bad([](FlowSettings& s) { s.axis = 3; });
  bad([](FlowSettings& s) { s.density_drop = NAN; });
  bad([](FlowSettings& s) { s.density_drop = 0; });
  PoreLattice solid = p;
  std::fill(solid.fluid.begin(), solid.fluid.end(), 0);
  CHECK_THROWS_AS(FlowSolver(solid, pressure_settings()), cmp::UsageError);
  PoreLattice wrong = p;
  wrong.fluid.pop_back();
  CHECK_THROWS_AS(FlowSolver(wrong, pressure_settings()), cmp::UsageError);
}

namespace {

// Checks of a flow that settles as kappa = 1 + a r^j, tau_H = 2 (check j).
std::vector<FlowObservables> creeping(long checks, double a, double r) {
  std::vector<FlowObservables> h;
  for (long j = 0; j < checks; ++j) {
    FlowObservables o;
    o.steps = 100 * (j + 1);
    o.kappa_lu = 1 + a * std::pow(r, static_cast<double>(j));
    o.tortuosity = 2;
    h.push_back(o);
  }
  return h;
}

}  // namespace

TEST_CASE("steady state: a slow creep is not stopped early, a fast one stops at once") {
  const ConvergenceSettings s{1e-6, 100, 10, 100000000};
  // Decay time 10^5 checks: the change over one window is below tol long before the flow is
  // within tol of its limit (the rule of a window's change alone stopped 100 times too early).
  for (double r : {1 - 1e-5, 1 - 1e-3, 0.9}) {
    long first = -1, window_only = -1;
    std::vector<FlowObservables> h;
    for (long j = 0; j < 5000000 && first < 0; ++j) {
      FlowObservables o;
      o.kappa_lu = 1 + 0.1 * std::pow(r, static_cast<double>(j));
      o.tortuosity = 2;
      h.push_back(o);
      const long k = static_cast<long>(h.size());
      if (window_only < 0 && k > 10 && std::abs(h[k - 1].kappa_lu - h[k - 11].kappa_lu) <= s.tol * h[k - 1].kappa_lu)
        window_only = k;
      if (steady(h, s)) first = k;
    }
    REQUIRE(first > 0);
    const double left = 0.1 * std::pow(r, static_cast<double>(first - 1));
    INFO("r " << r << ": steady at check " << first << " (window alone: " << window_only << "), " << left << " left");
    CHECK(left <= 1e-6 * 1.05);  // (the tail estimated from two windows' changes)
    if (r > 0.99) CHECK(window_only < first);
  }
  // A damped oscillation (sound waves) is steady only once its swings are below tol.
  std::vector<FlowObservables> h;
  for (long j = 0; j < 400; ++j) {
    FlowObservables o;
    o.kappa_lu = 1 + 1e-3 * std::pow(0.97, static_cast<double>(j)) * std::cos(0.7 * static_cast<double>(j));
    o.tortuosity = 2;
    h.push_back(o);
    if (steady(h, s)) {
      CHECK(1e-3 * std::pow(0.97, static_cast<double>(j)) < 2e-6);
      break;
    }
  }
  // Before two windows of checks nothing is steady; a flat history is.
  CHECK_FALSE(steady(creeping(20, 0, 0.5), s));
  CHECK(steady(creeping(21, 0, 0.5), s));
}
