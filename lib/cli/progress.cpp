#include "cli/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>

namespace cmp::cli {

namespace {
std::atomic<bool> g_line_open{false};
}

bool progress_line_open() noexcept { return g_line_open.load(); }

ProgressBar::ProgressBar(std::string label, double total, bool quiet)
    : label_(std::move(label)),
      total_(total > 0 ? total : 1),
      enabled_(!quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (!enabled_) return;
  enabled_ = false;
  if (g_line_open.exchange(false)) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
}

void ProgressBar::update(double done) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  if (!enabled_) return;
  done_ = done;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
  last_draw_ = now;
  draw(done);
}

void ProgressBar::set_note(std::string note, bool force_draw) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  if (!enabled_) return;
  note_ = std::move(note);
  if (force_draw) draw(done_);
}

void ProgressBar::draw(double done) {
  const auto now = std::chrono::steady_clock::now();
  const double fraction = std::clamp(done / total_, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const int width = 30, filled = static_cast<int>(fraction * width);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.0fs left%s%s\033[K", label_.c_str(), bar.c_str(), 100 * fraction, eta,
               note_.empty() ? "" : "  ", note_.c_str());
  std::fflush(stderr);
  g_line_open.store(true);
}

}  // namespace cmp::cli
