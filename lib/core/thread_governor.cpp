#include "core/thread_governor.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <utility>

namespace cmp {

namespace {
constexpr double kProbeSeconds = 0.005;
constexpr double kFirstExploitSeconds = 0.05;
constexpr double kLongestExploitSeconds = 1.0;
// The other choice must be this much faster to take over: noise does not make it flip.
constexpr double kMargin = 1.05;
// A first epoch shorter than this measures too few iterations to compare.
constexpr double kShortestFirstSeconds = 0.01;
// A probe lasts at least one iteration of the other choice, which may be far longer than the
// probe's nominal 5 ms: lbflow's thesis-sized lattice steps for ~45 ms, and under load a pair of
// two-thread steps of a small lattice took 30-35 ms against 6 on one thread. A long epoch that
// follows a confirming probe therefore lasts at least this many times the probe, so probing
// costs at most ~2 % (with epochs by time alone, 50 ms to 1 s, such probes took 10-30 % of a
// loaded run); right after a switch the next probe still comes after kFirstExploitSeconds, so
// a switch a noisy probe misled is undone soon.
constexpr double kExploitPerProbe = 50;

// What the last governor learned, for the next one: a run makes thousands of short
// relaxations, and each starting afresh on all threads (50 ms before its first probe) spent
// most of a loaded run on the slow choice. The next governor takes over the choice and the
// time its next probe is due.
struct Memory {
  int most = 0, chosen = 0;
  double exploit_seconds = 0;
  double probe_due = 0;  // on the clock of the governor that wrote it
};
std::mutex memory_mutex;
Memory memory;
}  // namespace

void ThreadGovernor::forget() {
  std::lock_guard lock(memory_mutex);
  memory = Memory{};
}

double ThreadGovernor::steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ThreadGovernor::ThreadGovernor(int threads, Clock clock) : clock_(std::move(clock)) {
  saved_ = omp_get_max_threads();
  most_ = threads > 0 ? threads : saved_;
  active_ = most_ > 1 && !omp_in_parallel();
  chosen_ = current_ = active_ ? most_ : 1;
  exploit_seconds_ = kFirstExploitSeconds;
  if (!active_) return;
  // A fresh governor compares soon: under load its first epoch on two threads ran at a fifth of
  // one thread's speed (lbflow at M = 1: 50 ms of 30 ms steps).
  double first = kShortestFirstSeconds;
  {
    std::lock_guard lock(memory_mutex);
    if (memory.most == most_) {
      chosen_ = memory.chosen;
      exploit_seconds_ = memory.exploit_seconds;
      first = std::max(memory.probe_due - now(), kShortestFirstSeconds);
    }
  }
  current_ = saved_;  // start_epoch sets the thread count when it differs from this
  start_epoch(chosen_, first);
}

ThreadGovernor::~ThreadGovernor() {
  if (!active_) return;
  omp_set_num_threads(saved_);
  std::lock_guard lock(memory_mutex);
  memory.most = most_;
  memory.chosen = chosen_;
  memory.exploit_seconds = exploit_seconds_;
  // Mid-probe, the next governor probes soon; otherwise when this long epoch would have ended.
  memory.probe_due = probing_ ? now() : epoch_start_ + epoch_seconds_;
}

void ThreadGovernor::start_epoch(int threads, double seconds) {
  if (threads != current_) omp_set_num_threads(threads);
  current_ = threads;
  epoch_seconds_ = seconds;
  epoch_ticks_ = 0;
  epoch_start_ = now();
}

void ThreadGovernor::tick() {
  if (!active_) return;
  ++epoch_ticks_;
  const double elapsed = now() - epoch_start_;
  if (elapsed < epoch_seconds_) return;
  const double rate = static_cast<double>(epoch_ticks_) / elapsed;
  const int other = chosen_ == most_ ? 1 : most_;
  if (!probing_) {
    // A long epoch ended: remember its speed, then try the other choice briefly.
    rate_current_ = rate;
    probing_ = true;
    start_epoch(other, kProbeSeconds);
    return;
  }
  probing_ = false;
  if (rate > kMargin * rate_current_) {
    chosen_ = current_;
    ++switches_;
    exploit_seconds_ = kFirstExploitSeconds;  // soon checked again: a noisy probe may have misled
  } else {
    exploit_seconds_ = std::max(std::min(2 * exploit_seconds_, kLongestExploitSeconds), kExploitPerProbe * elapsed);
  }
  start_epoch(chosen_, exploit_seconds_);
}

}  // namespace cmp
