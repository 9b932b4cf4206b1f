#pragma once
// A list of numbers as an option gives it: an inclusive range FIRST:LAST:STEP ("0.6:0.8:0.05"
// is 0.6, 0.65, ..., 0.8, LAST included when it lies on the grid within 1e-9 steps) or a comma
// list ("0.6,0.7"). The one parser of such options (shellpack compress --phi/--dphi, jam2d
// sweep --dphi); each caller then checks the values' own range.
#include <string>
#include <vector>

namespace cmp::cli {

// The values in order as given (a range ascending). Throws cmp::UsageError for a token that is
// not a finite number, a step that is not positive, LAST below FIRST, more than 100000 values,
// or any other shape.
std::vector<double> parse_value_list(const std::string& text);

// text cut at every sep ("a,,b," -> a, "", b, ""); "" gives none.
std::vector<std::string> split_fields(const std::string& text, char sep);

}  // namespace cmp::cli
