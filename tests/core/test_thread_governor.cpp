#include "core/thread_governor.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

#include <chrono>
#include <thread>

namespace {

// Runs ticks for about `seconds`, each taking `slow` when the OpenMP thread count is `slow_threads`
// and `fast` otherwise, as an iteration would under load; returns the thread count at the end.
int settle(cmp::ThreadGovernor& g, int slow_threads, double seconds) {
  using namespace std::chrono;
  const auto end = steady_clock::now() + duration<double>(seconds);
  while (steady_clock::now() < end) {
    const bool slow = omp_get_max_threads() == slow_threads;
    std::this_thread::sleep_for(microseconds(slow ? 400 : 100));
    g.tick();
  }
  return g.threads();
}

}  // namespace

TEST_CASE("thread governor: moves to one thread when two run slower and back when they run faster") {
  omp_set_num_threads(2);
  cmp::ThreadGovernor::forget();
  {
    cmp::ThreadGovernor g(2);
    CHECK(g.threads() == 2);
    CHECK(settle(g, 2, 0.4) == 1);  // two threads four times slower: one thread wins
    CHECK(omp_get_max_threads() == 1);
    CHECK(settle(g, 1, 2.5) == 2);  // the load went away: back to two
    CHECK(g.switches() >= 2);
  }
  CHECK(omp_get_max_threads() == 2);  // restored
}

TEST_CASE("thread governor: long iterations are probed rarely") {
  // Iterations of 20 ms (lbflow's thesis-sized lattice steps for ~45 ms), as fast on either
  // choice: each probe costs a whole iteration, so a long epoch must hold at least 50 of them.
  // With epochs by time alone (50, 100, 200, 400, 800 ms) 75 iterations held 4 probes.
  omp_set_num_threads(2);
  cmp::ThreadGovernor::forget();
  cmp::ThreadGovernor g(2);
  int probes = 0;
  for (int k = 0; k < 75; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    g.tick();
    if (k < 74 && g.threads() == 1) ++probes;  // the next iteration is a probe
  }
  INFO("probes in 75 iterations of 20 ms: " << probes);
  CHECK(probes >= 1);
  CHECK(probes <= 2);
}

TEST_CASE("thread governor: probes of a choice whose iterations are long under load are rare") {
  // lbflow at M = 1 with another process on one core: a pair of steps took ~6 ms on one thread
  // and 30-35 ms on two, so each probe of two threads cost a 30 ms iteration. With epochs by
  // time alone (50 ms to 1 s) such probes took 4.5 % of this 2 s run; at least 50 probe
  // lengths per long epoch keep them at 1.5 %.
  omp_set_num_threads(2);
  cmp::ThreadGovernor::forget();
  {
    cmp::ThreadGovernor g(2);
    REQUIRE(settle(g, 2, 0.4) == 1);
  }
  cmp::ThreadGovernor g(2);
  using namespace std::chrono;
  const auto start = steady_clock::now();
  const auto end = start + duration<double>(2.0);
  double on_two = 0;
  while (steady_clock::now() < end) {
    const bool two = omp_get_max_threads() == 2;
    const auto t0 = steady_clock::now();
    std::this_thread::sleep_for(microseconds(two ? 30000 : 1000));
    g.tick();
    if (two) on_two += duration<double>(steady_clock::now() - t0).count();
  }
  const double share = on_two / duration<double>(steady_clock::now() - start).count();
  INFO("share of the run on two threads: " << share);
  CHECK(g.threads() == 1);
  CHECK(share < 0.03);
}

TEST_CASE("thread governor: inert for one thread and inside a parallel region") {
  omp_set_num_threads(2);
  cmp::ThreadGovernor one(1);
  CHECK(one.threads() == 1);
  CHECK(settle(one, 1, 0.05) == 1);
  CHECK(omp_get_max_threads() == 2);
  int inside = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    {
      cmp::ThreadGovernor nested(2);
      inside = nested.threads();
    }
  }
  CHECK(inside == 1);
}

TEST_CASE("thread governor: a new governor starts with the choice the last one made") {
  // A loaded run makes many short relaxations: each must not start over on the slow choice.
  omp_set_num_threads(2);
  cmp::ThreadGovernor::forget();
  {
    cmp::ThreadGovernor g(2);
    CHECK(settle(g, 2, 0.4) == 1);
  }
  CHECK(omp_get_max_threads() == 2);  // restored between governors
  for (int k = 0; k < 20; ++k) {
    cmp::ThreadGovernor next(2);
    CHECK(next.threads() == 1);
    CHECK(omp_get_max_threads() == 1);
    settle(next, 2, 0.01);  // shorter than an epoch: no probe of two threads
  }
  {
    // The load went away: a long enough relaxation still finds two threads again.
    cmp::ThreadGovernor later(2);
    CHECK(settle(later, 1, 2.5) == 2);
  }
  cmp::ThreadGovernor::forget();
  cmp::ThreadGovernor fresh(2);
  CHECK(fresh.threads() == 2);
}
