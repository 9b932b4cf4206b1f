#pragma once
// --volume-rule, wired one way for `shellpack shell` and `shellpack compress`: declared with the
// options, parsed with the checks (a bad name is reported with every other bad option).
#include "cli/tool.hpp"
#include "shell/relax.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace cmp::shellpack {

struct VolumeRuleOption {
  std::string name = shell::volume_rule_name(shell::VolumeRuleKind::Projected);

  void add(CLI::App& app) {
    app.add_option("--volume-rule", name,
                   "constant volume, how Pi is found: projected (every volume held at its target inside FIRE, Pi "
                   "the constraint's multiplier), accelerated (Pi updated between and inside relaxations, the mean "
                   "gap closed by a secant, overshooting shells damped) or thesis (Pi <- Pi (1 + (V0 - V)/V), "
                   "5.2.1); the same fixed point, within 0.1 % of each volume for the updated rules")
        ->capture_default_str();
  }
  void apply(cli::Tool& tool, shell::RelaxParameters& relax) const {
    tool.collect("--volume-rule", [&] { relax.volume_rule = shell::parse_volume_rule(name); });
  }
};

}  // namespace cmp::shellpack
