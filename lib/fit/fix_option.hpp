#pragma once
// kcfit's --fix option: parameters held at a value, "name=value[,name=value]", the option
// repeatable, as the (name, value) pairs of FitOptions::fixed.
#include <string>
#include <utility>
#include <vector>

namespace cmp::fit {

// The pairs of every item of every argument, in order. An item without a name before '=' or
// whose value is not a finite number (io::try_parse_double) is left out and its message
// ("expected name=value[,name=value], ...; got 'item'", "'v' is not a finite number (in
// item)") appended to problems, for the caller to report under --fix. Whether the names are
// parameters of the model is fit()'s check.
std::vector<std::pair<std::string, double>> parse_fix(const std::vector<std::string>& args,
                                                      std::vector<std::string>& problems);

}  // namespace cmp::fit
