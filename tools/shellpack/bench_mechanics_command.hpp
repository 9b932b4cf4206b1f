#pragma once
// `shellpack bench-mechanics`: one Appendix B benchmark as CSV (computed beside the analytic
// curve), or the analytic curve alone.
#include "cli/tool.hpp"

#include <string>

namespace cmp::shellpack {

class BenchMechanicsCommand {
 public:
  // Adds the subcommand and its options to `parent`; `common` takes --threads, -q.
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common);
  // Checks the case name (problems collected in `tool`).
  void check(cli::Tool& tool) const;
  // Writes the CSV (whole, or nothing on an error); notes go to stderr unless quiet.
  void run(bool quiet, const std::string& provenance) const;

 private:
  std::string case_, output_ = "-";
  bool full_ = false, analytic_ = false;
};

}  // namespace cmp::shellpack
