#pragma once
// Picks, while an iterative computation runs, between all OpenMP threads and one, by the
// speed it measures. An iteration of a few hundred microseconds forks and joins threads
// several times; when another process holds a core (make -j, a shared node) each join waits
// for a descheduled thread, and two threads can run many times slower than one. Results do
// not depend on the choice (the parallel passes sum fixed chunks in a fixed order), so the
// governor may switch at any iteration.
//
// It alternates short probe epochs (about 5 ms) of the other choice with long epochs of the
// faster one (growing from 50 ms to about 1 s while the choice holds, and never shorter than
// 50 times the probe before it, which lasts at least one iteration of the other choice), so a
// wrong guess costs a few per cent at most; a fresh governor's first epoch is 10 ms. The choice carries over
// from one governor to the next in the process (a run makes many short relaxations), as does
// the time the next probe is due.
//
// Time comes from a clock that can be injected: the default reads std::chrono::steady_clock,
// and the tests give one whose time advances by the cost they assign each iteration, so the
// decisions are tested without any dependence on the machine's speed or load.
#include <functional>

namespace cmp {

class ThreadGovernor {
 public:
  // A clock in seconds (any origin, never going back).
  using Clock = std::function<double()>;
  // The default clock: std::chrono::steady_clock in seconds.
  static double steady_seconds();

  // threads: the most the caller would use (0: omp_get_max_threads()). Inert when that is 1
  // or when called inside a parallel region (the inner regions run on one thread anyway).
  // clock: where time comes from (empty: steady_seconds).
  explicit ThreadGovernor(int threads = 0, Clock clock = {});
  // Restores the thread count it found.
  ~ThreadGovernor();
  ThreadGovernor(const ThreadGovernor&) = delete;
  ThreadGovernor& operator=(const ThreadGovernor&) = delete;

  // Marks the end of one iteration; may change the OpenMP thread count for the next ones.
  void tick();
  // The thread count in use now.
  int threads() const { return current_; }
  // How many times the choice changed (for tests and benchmarks).
  long switches() const { return switches_; }
  // Drops what earlier governors learned: the next starts on all threads (for tests).
  static void forget();

 private:
  void start_epoch(int threads, double seconds);
  double now() const { return clock_ ? clock_() : steady_seconds(); }

  int saved_ = 1, most_ = 1, current_ = 1;
  bool active_ = false, probing_ = false;
  Clock clock_;
  double epoch_start_ = 0;
  double epoch_seconds_ = 0;   // length of the epoch in progress
  double exploit_seconds_ = 0; // length of the next long epoch
  long epoch_ticks_ = 0;
  double rate_current_ = 0;    // iterations per second of the last long epoch
  int chosen_ = 1;             // the choice the long epochs use
  long switches_ = 0;
};

}  // namespace cmp
