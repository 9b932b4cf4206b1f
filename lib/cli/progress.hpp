#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal and the user did not ask for
// --quiet (DESIGN.md), redrawn at most ten times a second so it costs nothing in hot loops.
#include <chrono>
#include <string>

namespace cmp::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, double total, bool quiet);
  ~ProgressBar();  // clears the line
  // Reports that `done` of `total` units are finished; cheap to call often.
  void update(double done);
  bool enabled() const { return enabled_; }

 private:
  std::string label_;
  double total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace cmp::cli
