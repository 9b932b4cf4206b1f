#pragma once
// `shellpack bench-mechanics`: one Appendix B benchmark as CSV (computed beside the analytic
// curve), or the analytic curve alone.
#include "cli/tool.hpp"
#include "command.hpp"

#include <string>

namespace cmp::shellpack {

class BenchMechanicsCommand final : public Command {
 public:
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  // Checks the case name (problems collected in `tool`).
  void check(cli::Tool& tool) override;
  // Writes the CSV (whole, or nothing on an error); notes go to stderr unless quiet.
  void run(bool quiet, const std::string& provenance) override;

 private:
  std::string case_, output_ = "-";
  bool full_ = false, analytic_ = false;
};

}  // namespace cmp::shellpack
