#pragma once
// --volume-rule, wired one way for `shellpack shell` and `shellpack compress`: declared with the
// options, parsed with the checks (a bad name is reported with every other bad option).
#include "cli/tool.hpp"
#include "shell/relax.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace cmp::shellpack {

struct VolumeRuleOption {
  std::string name = shell::volume_rule_name(shell::VolumeRuleKind::Accelerated);

  void add(CLI::App& app) {
    app.add_option("--volume-rule", name,
                   "constant volume, how Pi moves between relaxations: accelerated (the mean gap closed by a secant, "
                   "overshooting shells damped) or thesis (Pi <- Pi (1 + (V0 - V)/V), 5.2.1: the same fixed point, "
                   "more updates towards confluence)")
        ->capture_default_str();
  }
  void apply(cli::Tool& tool, shell::RelaxParameters& relax) const {
    tool.collect("--volume-rule", [&] { relax.volume_rule = shell::parse_volume_rule(name); });
  }
};

}  // namespace cmp::shellpack
