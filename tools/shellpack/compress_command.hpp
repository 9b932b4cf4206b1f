#pragma once
// `shellpack compress`: its options and their defaults (the thesis's Ch. 5 shells), the checks
// of every option at once, and the run with the provenance a resumed run repeats.
#include "cli/tool.hpp"
#include "command.hpp"
#include "packrun/compress_job.hpp"
#include "volume_rule_option.hpp"

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace cmp::shellpack {

class CompressCommand final : public Command {
 public:
  // args: the full command line as it is parsed (with a checkpoint's arguments,
  // with_checkpoint_args): what a checkpoint records.
  explicit CompressCommand(std::vector<std::string> args) : args_(std::move(args)) {}
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  void check(cli::Tool& tool) override;
  // Runs the job under the provenance of the run the checkpoint records (an interrupted and
  // resumed run writes the same bytes as one never stopped), not the one given.
  void run(bool quiet, const std::string& provenance) override;

 private:
  std::vector<std::string> args_;
  const cli::CommonOptions* common_ = nullptr;  // --seed, --threads, -q, shared with main
  packrun::CompressJob job;
  std::string phi, dphi;  // --phi, --dphi as typed
  double p0 = 0.0025;     // --P0 [E]
  double wall_modulus = std::numeric_limits<double>::infinity();  // --wall-modulus [E]
  bool no_penetration_check = false;
  VolumeRuleOption volume_rule;
};

// `shellpack compress --resume FILE [options]`: the checkpoint's arguments, then the ones
// typed (the last wins). Returns argv unchanged for any other command line.
std::vector<std::string> with_checkpoint_args(int argc, char** argv);

}  // namespace cmp::shellpack
