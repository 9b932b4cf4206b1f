#pragma once
// `shellpack shell`: one pressurised elastic shell, inflated and optionally squeezed between two
// plates (App. B); its options, their checks and the run (or the list of registered models).
#include "cli/tool.hpp"
#include "command.hpp"
#include "packrun/shell_job.hpp"
#include "volume_rule_option.hpp"

#include <string>

namespace cmp::shellpack {

class ShellCommand final : public Command {
 public:
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  // Checks every option (problems collected in `tool`) and completes the job.
  void check(cli::Tool& tool) override;
  // Runs the job, or writes the model list (--list-models) to stdout.
  void run(bool quiet, const std::string& provenance) override;

 private:
  packrun::ShellJob job_;
  double vertex_radius_ = 0, wall_gap_ = 0;
  bool list_models_ = false;
  VolumeRuleOption volume_rule_;
};

}  // namespace cmp::shellpack
