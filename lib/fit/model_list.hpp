#pragma once
// kcfit --list-models: every model of models.hpp with its formula, source, domain, default
// columns and parameters, then the CSV columns the tools write that kcfit reads.
#include <ostream>

namespace cmp::fit {

// Writes the list to out, models in the order of models().
void write_model_list(std::ostream& out);

}  // namespace cmp::fit
