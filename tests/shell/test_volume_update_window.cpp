// When Pi moves inside a constant-volume relaxation (lib/shell/volume_update_window.hpp), on
// residual sequences like those FIRE produces.
#include "shell/volume_update_window.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using cmp::shell::VolumeUpdateWindow;

namespace {

// Pi moves at every check that opens (a shell always off its volume, by error(it)); returns the
// updates made.
template <class Residual, class Error>
int updates_over(VolumeUpdateWindow& window, long iterations, Residual residual, Error error) {
  int updates = 0;
  for (long it = 0; it < iterations; ++it) {
    const double r = residual(it);
    if (window.open(it, r)) {
      window.moved(r, error(it));
      ++updates;
    }
  }
  return updates;
}

}  // namespace

TEST_CASE("volume update window: closed above factor x tolerance, then every interval iterations", "[shell][volume]") {
  VolumeUpdateWindow window(1e-5, 100, 20);
  CHECK_FALSE(window.open(100, 2e-3));
  CHECK(window.open(120, 1e-3));
  CHECK_FALSE(window.open(130, 5e-4));  // within the interval
  CHECK(window.open(140, 5e-4));
}

TEST_CASE("volume update window: updates that bring the volumes nearer keep it wide", "[shell][volume]") {
  VolumeUpdateWindow window(1e-5, 100, 20);
  // The residual wanders between 10 and 90 x tolerance while the volume error falls: a check at
  // 20, 40, ..., 1980.
  const auto wandering = [](long it) { return 1e-5 * (50 + 40 * std::sin(0.3 * static_cast<double>(it))); };
  const int n = updates_over(window, 2000, wandering, [](long it) { return 1e-2 / static_cast<double>(1 + it); });
  CHECK(n == 99);
}

TEST_CASE("volume update window: unhelpful updates wait for a residual lower than the last", "[shell][volume]") {
  // The stall of 16 x 642 shells at phi 0.95: each update leaves the residual between 30 and 160
  // times the tolerance and the volumes no nearer. Without the narrowing every 20th iteration
  // below 100 x tolerance updated (637 updates here, never converging); with it, only the
  // sampled residual's record lows do.
  VolumeUpdateWindow window(1e-5, 100, 20);
  const auto bouncing = [](long it) { return 1e-5 * (95 - 65 * std::sin(0.05 * static_cast<double>(it))); };
  const int n = updates_over(window, 20000, bouncing, [](long) { return 5e-3; });
  CHECK(n >= 1);
  CHECK(n <= 40);
}

TEST_CASE("volume update window: convergence always opens it", "[shell][volume]") {
  VolumeUpdateWindow window(1e-5, 100, 20);
  CHECK(window.open(20, 5e-5));
  window.moved(5e-5, 5e-3);
  CHECK(window.open(40, 6e-5));  // the first update has nothing to compare with
  window.moved(6e-5, 5e-3);      // no nearer: narrowed to 6e-5
  CHECK_FALSE(window.open(60, 7e-5));
  CHECK(window.open(61, 1e-5));  // converged: no interval, no narrowing
  window.moved(1e-5, 6e-3);
  CHECK(window.open(62, 0.9e-5));
}
