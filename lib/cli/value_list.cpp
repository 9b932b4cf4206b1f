#include "cli/value_list.hpp"

#include "core/errors.hpp"
#include "io/parse_number.hpp"

#include <cmath>
#include <sstream>

namespace cmp::cli {

namespace {
double parse_number(const std::string& token, const std::string& text) {
  double v = 0;
  if (!io::try_parse_double(token, v) || !std::isfinite(v))
    throw UsageError("'" + token + "' in '" + text + "' is not a number");
  return v;
}

}  // namespace

std::vector<std::string> split_fields(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string p; std::getline(in, p, sep);) parts.push_back(p);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

std::vector<double> parse_value_list(const std::string& text) {
  std::vector<double> out;
  const auto colon = split_fields(text, ':');
  if (colon.size() == 3) {
    const double first = parse_number(colon[0], text), last = parse_number(colon[1], text),
                 step = parse_number(colon[2], text);
    if (!(step > 0)) throw UsageError("the step of '" + text + "' must be positive");
    if (last < first) throw UsageError("'" + text + "': LAST is below FIRST");
    const long n = static_cast<long>(std::floor((last - first) / step + 1e-9));
    if (n > 100000) throw UsageError("'" + text + "' names more than 100000 values");
    for (long k = 0; k <= n; ++k) out.push_back(first + static_cast<double>(k) * step);
  } else if (colon.size() == 1) {
    for (const auto& t : split_fields(text, ',')) out.push_back(parse_number(t, text));
  } else {
    throw UsageError("expected FIRST:LAST:STEP or a comma list, got '" + text + "'");
  }
  if (out.empty()) throw UsageError("no value in '" + text + "'");
  return out;
}

}  // namespace cmp::cli
