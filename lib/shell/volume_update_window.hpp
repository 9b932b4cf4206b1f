#pragma once
// When Pi may move inside a constant-volume relaxation (relax.hpp): once FIRE's residual has
// fallen to `factor` times the force tolerance, every `interval` iterations; always at
// convergence. An update that finds the volumes no nearer their targets than the last one did
// narrows the window: the next update then needs a residual no higher than this one's.
//
// Why: an update reads the volumes of a shape still relaxing. Where those answer the relaxation
// more than Pi, each update kicks FIRE out of its descent and the next one reads other volumes:
// 16 shells of 642 vertices (jam seed 2) at phi = 0.95 made 790 updates in 34,000 iterations,
// the residual bouncing between 30 and 160 times the tolerance, and stopped at the
// 200,000-iteration cap; 50 shells of 2,562 vertices (jam seed 1) spent over 20 minutes in the
// step to phi = 0.787. With the narrowing those steps take 1,547 and 479 iterations. Narrowing
// only after an unhelpful update leaves healthy compressions as they were (116,585 and 115,890
// iterations to phi = 0.95 for 16 x 642, seeds 1 and 3, before; 114,445 and 116,619 after), where
// narrowing after every update cost 12-17 % more.
#include <algorithm>
#include <limits>

namespace cmp::shell {

class VolumeUpdateWindow {
 public:
  VolumeUpdateWindow(double tolerance, double factor, int interval)
      : tolerance_(tolerance), ceiling_(factor * tolerance), interval_(interval) {}

  // Whether the volumes are to be checked at FIRE iteration `it` with residual `max_force`.
  bool open(long it, double max_force) {
    if (!(max_force <= ceiling_)) return false;
    if (max_force > tolerance_ && it - last_check_ < interval_) return false;
    last_check_ = it;
    return true;
  }
  // Pi was moved at residual `max_force`, the volumes off their targets by `error` (the worst
  // relative error) before the move. No nearer than at the last update, before convergence: the
  // next update needs a residual no higher than this one.
  void moved(double max_force, double error) {
    if (max_force > tolerance_ && !(error < last_error_)) ceiling_ = std::min(ceiling_, max_force);
    last_error_ = error;
  }

 private:
  double tolerance_, ceiling_;
  int interval_;
  long last_check_ = 0;
  double last_error_ = std::numeric_limits<double>::infinity();
};

}  // namespace cmp::shell
