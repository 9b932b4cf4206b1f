#pragma once
// `shellpack structure`: g(r), Z, rattlers and contact forces of sphere packings; its options,
// their checks and the batch.
#include "cli/tool.hpp"
#include "command.hpp"
#include "packrun/structure_batch.hpp"

#include <string>

namespace cmp::shellpack {

class StructureCommand final : public Command {
 public:
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  // Checks the options (problems collected in `tool`).
  void check(cli::Tool& tool) override;
  void run(bool quiet, const std::string& provenance) override;

 private:
  packrun::StructureBatch batch_;
};

}  // namespace cmp::shellpack
