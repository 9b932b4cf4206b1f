#pragma once
// `shellpack analyze`: its options (the material and contact values that override a packing
// file's own only when given), their checks and the run.
#include "cli/tool.hpp"
#include "command.hpp"
#include "packrun/analyze_batch.hpp"

#include <string>

namespace cmp::shellpack {

class AnalyzeCommand final : public Command {
 public:
  CLI::App* add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) override;
  // Checks the options (problems collected in `tool`).
  void check(cli::Tool& tool) override;
  // Applies the overrides given and runs the batch.
  void run(bool quiet, const std::string& provenance) override;

 private:
  packrun::AnalyzeBatch batch_;
  double E_ = 1, nu_ = 0.5, rv_ = 1, delta_ = 1, d0_ = 1, p0_ = 1;
  std::string contact_;
  CLI::Option *E_opt_ = nullptr, *nu_opt_ = nullptr, *rv_opt_ = nullptr, *delta_opt_ = nullptr,
              *contact_opt_ = nullptr, *d0_opt_ = nullptr, *p0_opt_ = nullptr;
};

}  // namespace cmp::shellpack
