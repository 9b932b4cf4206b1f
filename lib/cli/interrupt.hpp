#pragma once
// Interrupted runs (docs/conventions.md): on SIGINT or SIGTERM a tool removes its temporaries (every
// io::AtomicOutput's, and the paths registered with io::TemporaryPath), clears its progress
// bar, says "tool: interrupted" on stderr and exits 130 (SIGINT) or 143 (SIGTERM), the
// statuses a shell gives a process killed by those signals.
#include <string>

namespace cmp::cli {

// Installs the handlers (cli::run_tool does it first thing). Child processes a tool starts
// (gnuplot) get the terminal's SIGINT themselves; a tool waiting for one should treat its
// death by a signal as an interruption, not as "gnuplot failed".
void install_interrupt_handlers(const std::string& tool);

// When the environment names a file in CMP_READY_FILE, creates it (empty): the options were
// checked, the handlers are installed and the work starts (Tool::finish_checks calls it), so
// a signal from now on is an interruption. The signal tests wait for that file instead of
// sleeping for a time that a slow or loaded machine may not respect.
void announce_work_started();

// The exit status of a run stopped by signal sig (128 + sig).
inline int interrupted_status(int sig) { return 128 + sig; }

}  // namespace cmp::cli
