#pragma once
// `shellpack shell`'s job around the protocol of lib/shell/shell_run: the mesh read and
// checked (closed, outward, walls clear) before any work, a progress bar and a warning for
// every step that stopped unconverged, then the table and the relaxed mesh written atomically
// (the CSV's temporary exists from the start, so a full disk shows before the run).
#include "shell/shell_run.hpp"

#include <string>

namespace cmp::packrun {

struct ShellJob {
  std::string mesh_path;           // closed outward triangle mesh (OFF; '-': stdin)
  std::string mesh_output;         // the relaxed mesh ("" none, '-' stdout)
  std::string csv = "-";           // the table ("" none, '-' stdout)
  shell::ShellRunOptions run;
  bool quiet = false;              // no bar, no summary line (warnings still)
};

// Throws cmp::InputError for a bad mesh, cmp::UsageError for walls that cut it, and what
// run_shell throws.
void run_shell_job(const ShellJob& job, const std::string& provenance);

}  // namespace cmp::packrun
