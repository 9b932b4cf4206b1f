#pragma once
// `shellpack jam`: its options (the thesis's 5.5.1 protocol and FIRE's parameters), the checks
// of every option at once and the batch of packings.
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "command.hpp"
#include "packrun/jam_batch.hpp"

#include <string>

namespace cmp::shellpack {

class JamCommand final : public Command {
 public:
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  // Checks every option (problems collected in `tool`) and completes the batch.
  void check(cli::Tool& tool) override;
  void run(bool quiet, const std::string& provenance) override;

 private:
  packrun::JamBatch batch_;
  cli::SeedOptions seeding_;
  bool keep_rattlers_ = false, allow_hyperstatic_ = false;
};

}  // namespace cmp::shellpack
