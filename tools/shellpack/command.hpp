#pragma once
// One shellpack subcommand: its options, the checks of every option at once and the run. Each
// lives in its own <name>_command file; main adds them all, checks and runs the one parsed.
#include "cli/tool.hpp"

#include <string>

namespace cmp::shellpack {

class Command {
 public:
  virtual ~Command() = default;
  // Adds the subcommand and its options to `parent`; `common` takes the options every
  // subcommand shares (--threads, -q, --seed where it has one).
  virtual CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) = 0;
  // Checks every option (problems collected in `tool`) and completes the job.
  virtual void check(cli::Tool& tool) = 0;
  // Runs the job; `provenance` heads its files.
  virtual void run(bool quiet, const std::string& provenance) = 0;
};

}  // namespace cmp::shellpack
