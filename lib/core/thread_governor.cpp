#include "core/thread_governor.hpp"

#include <omp.h>

#include <algorithm>

namespace cmp {

namespace {
constexpr double kProbeSeconds = 0.005;
constexpr double kFirstExploitSeconds = 0.05;
constexpr double kLongestExploitSeconds = 1.0;
// The other choice must be this much faster to take over: noise does not make it flip.
constexpr double kMargin = 1.05;
}  // namespace

ThreadGovernor::ThreadGovernor(int threads) {
  saved_ = omp_get_max_threads();
  most_ = threads > 0 ? threads : saved_;
  active_ = most_ > 1 && !omp_in_parallel();
  chosen_ = current_ = active_ ? most_ : 1;
  exploit_seconds_ = kFirstExploitSeconds;
  if (active_) start_epoch(most_, kFirstExploitSeconds);
}

ThreadGovernor::~ThreadGovernor() {
  if (active_) omp_set_num_threads(saved_);
}

void ThreadGovernor::start_epoch(int threads, double seconds) {
  if (threads != current_) omp_set_num_threads(threads);
  current_ = threads;
  epoch_seconds_ = seconds;
  epoch_ticks_ = 0;
  epoch_start_ = Clock::now();
}

void ThreadGovernor::tick() {
  if (!active_) return;
  ++epoch_ticks_;
  const double elapsed = std::chrono::duration<double>(Clock::now() - epoch_start_).count();
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
    exploit_seconds_ = kFirstExploitSeconds;
  } else {
    exploit_seconds_ = std::min(2 * exploit_seconds_, kLongestExploitSeconds);
  }
  start_epoch(chosen_, exploit_seconds_);
}

}  // namespace cmp
