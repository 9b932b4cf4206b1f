#pragma once
// kcfit --list-models: every model of models.hpp as CSV, the columns every tool's listing has
// (kind,name,description; the description is where in the thesis) and then its formula, domain,
// parameters and default x and y columns (the first present in the input wins).
#include <ostream>

namespace cmp::fit {

// Writes the list to out, models in the order of models().
void write_model_list(std::ostream& out);

}  // namespace cmp::fit
