#pragma once
// --volume-rule, as `shellpack shell` and `shellpack compress` both take it: the constant-volume
// update with a gain per shell (adaptive, lib/shell/volume_rule.hpp) or the thesis's g = 1.
#include "shell/relax.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace cmp::shellpack {

inline CLI::Option* add_volume_rule_option(CLI::App& app, shell::RelaxParameters& relax) {
  return app
      .add_option_function<std::string>(
          "--volume-rule", [&relax](const std::string& rule) { relax.adaptive_volume_gain = rule == "adaptive"; },
          "constant volume: Pi <- Pi (1 + g (V0 - V)/V) with a gain g per shell that grows while the updates fall "
          "short (adaptive) or g = 1 (thesis, 5.2.1: more updates towards confluence)")
      ->check(CLI::IsMember({"adaptive", "thesis"}))
      ->default_str("adaptive");
}

}  // namespace cmp::shellpack
