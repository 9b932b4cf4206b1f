#include "cli/interrupt.hpp"

#include "cli/progress.hpp"
#include "io/atomic_output.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cmp::cli {

namespace {
char g_message[256];  // "tool: interrupted\n", built before any signal can come
std::size_t g_message_length = 0;

extern "C" void on_interrupt(int sig) {
  // Only async-signal-safe calls from here on: unlink, rmdir, write, _exit.
  io::remove_registered_temporaries();
  if (progress_line_open()) {
    const char clear[] = "\r\033[K";
    [[maybe_unused]] auto r = ::write(STDERR_FILENO, clear, sizeof clear - 1);
  }
  [[maybe_unused]] auto r = ::write(STDERR_FILENO, g_message, g_message_length);
  ::_exit(interrupted_status(sig));
}
}  // namespace

void install_interrupt_handlers(const std::string& tool) {
  const std::string message = tool.substr(0, sizeof g_message - 20) + ": interrupted\n";
  std::memcpy(g_message, message.c_str(), message.size());
  g_message_length = message.size();
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = 0;
  for (int sig : {SIGINT, SIGTERM}) {
    // A shell starts background jobs with SIGINT ignored; keep it ignored then, as the
    // standard tools do.
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (sig == SIGINT && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &action, nullptr);
  }
}

void announce_work_started() {
  const char* path = std::getenv("CMP_READY_FILE");
  if (path == nullptr || *path == '\0') return;
  std::FILE* f = std::fopen(path, "w");
  if (f != nullptr) std::fclose(f);
}

}  // namespace cmp::cli
