#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal and the user did not ask for
// --quiet (docs/conventions.md), redrawn at most ten times a second so it costs nothing in hot loops.
// The bar owns its line: call finish() (or let the bar go out of scope) before printing
// anything else to stderr, so a summary starts on a line of its own.
#include <chrono>
#include <atomic>
#include <mutex>
#include <string>

namespace cmp::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, double total, bool quiet);
  ~ProgressBar();  // finish()
  // Reports that `done` of `total` units are finished; cheap to call often, from any thread.
  void update(double done);
  // Text shown after the bar, e.g. "try 12, rejected: 8 not isostatic"; drawn at the next
  // update (or now when force_draw).
  void set_note(std::string note, bool force_draw = false);
  // Clears the bar's line so the next message starts at the left margin. Idempotent; after
  // it the bar draws nothing more.
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void draw(double done);
  std::string label_, note_;
  double total_, done_ = 0;
  std::atomic<bool> enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

// True while some progress bar's line is on the terminal (not yet finished): a signal handler
// reads it to clear the line before its message.
bool progress_line_open() noexcept;

}  // namespace cmp::cli
