#pragma once
// `shellpack structure`: g(r), Z, rattlers and contact forces of sphere packings; its options,
// their checks and the batch.
#include "cli/tool.hpp"
#include "packrun/structure_batch.hpp"

#include <string>

namespace cmp::shellpack {

class StructureCommand {
 public:
  // Adds the subcommand and its options to `parent`; `common` takes --threads, -q.
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common);
  // Checks the options (problems collected in `tool`).
  void check(cli::Tool& tool) const;
  void run(bool quiet, const std::string& provenance);

 private:
  packrun::StructureBatch batch_;
};

}  // namespace cmp::shellpack
