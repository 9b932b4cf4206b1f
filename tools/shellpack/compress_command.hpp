#pragma once
// `shellpack compress`: its options and their defaults (the thesis's Ch. 5 shells), the checks
// of every option at once, and the run with the provenance a resumed run repeats.
#include "cli/tool.hpp"
#include "packrun/compress_job.hpp"
#include "volume_rule_option.hpp"

#include <limits>
#include <string>
#include <vector>

namespace cmp::shellpack {

struct CompressCommand {
  packrun::CompressJob job;
  std::string phi, dphi;  // --phi, --dphi as typed
  double p0 = 0.0025;     // --P0 [E]
  double wall_modulus = std::numeric_limits<double>::infinity();  // --wall-modulus [E]
  bool no_penetration_check = false;
  VolumeRuleOption volume_rule;

  // Adds the subcommand and its options to `parent`; `common` takes --seed, --threads, -q.
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common);
  // Checks every option (problems collected in `tool`) and completes the job; args: the full
  // command line as parsed (with a checkpoint's arguments, with_checkpoint_args).
  void check(cli::Tool& tool, const cli::CommonOptions& common, const std::vector<std::string>& args);
  // Runs the job.
  void run();
};

// `shellpack compress --resume FILE [options]`: the checkpoint's arguments, then the ones
// typed (the last wins). Returns argv unchanged for any other command line.
std::vector<std::string> with_checkpoint_args(int argc, char** argv);

}  // namespace cmp::shellpack
