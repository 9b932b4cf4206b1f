#pragma once
// The registered shell styles, one explicit table per kind. A CLI lists a table for
// --list-models and builds a style by name from the same entries; the generic test harness
// (tests/forcefield) checks every entry of every table against its energy.
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <memory>
#include <ostream>
#include <span>
#include <string>

namespace cmp::shell {

template <class Parameters>
struct Style {
  using parameters_type = Parameters;
  const char* name;         // as given on the command line, e.g. "svk"
  const char* description;  // one line for --list-models
  // Builds the term on the rest mesh; throws cmp::UsageError for bad parameters or mesh.
  std::unique_ptr<EnergyTerm> (*make)(const mesh::TriMesh& rest, const Parameters& p);
};

using StretchingStyle = Style<MaterialParameters>;
using BendingStyle = Style<MaterialParameters>;
using PressureStyle = Style<PressureParameters>;
using ContactStyle = Style<ContactParameters>;
using LoadStyle = Style<LoadParameters>;

std::span<const StretchingStyle> stretching_styles();
std::span<const BendingStyle> bending_styles();
std::span<const PressureStyle> pressure_styles();
std::span<const ContactStyle> contact_styles();
std::span<const LoadStyle> load_styles();

// The entry called `name`; throws cmp::UsageError "unknown <kind> model 'x' (known: a, b)".
const StretchingStyle& stretching_style(const std::string& name);
const BendingStyle& bending_style(const std::string& name);
const PressureStyle& pressure_style(const std::string& name);
const ContactStyle& contact_style(const std::string& name);
const LoadStyle& load_style(const std::string& name);

// Every registered style of every kind as CSV (kind,name,description), from the tables above:
// what `shellpack shell --list-models` prints.
void write_model_list(std::ostream& out);

}  // namespace cmp::shell
