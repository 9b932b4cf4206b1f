#include "fit/fix_option.hpp"

#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <sstream>

namespace cmp::fit {

std::vector<std::pair<std::string, double>> parse_fix(const std::vector<std::string>& args,
                                                      std::vector<std::string>& problems) {
  std::vector<std::pair<std::string, double>> fixed;
  for (const auto& arg : args) {
    std::stringstream items(arg);
    std::string item;
    while (std::getline(items, item, ',')) {
      const auto eq = item.find('=');
      double value = 0;
      if (eq == std::string::npos || eq == 0)
        problems.push_back("expected name=value[,name=value], e.g. --fix phi_c=0.141; got '" + item + "'");
      else if (!io::try_parse_double(item.substr(eq + 1), value))
        problems.push_back(fmt::format("'{}' is not a finite number (in {})", item.substr(eq + 1), item));
      else
        fixed.emplace_back(item.substr(0, eq), value);
    }
  }
  return fixed;
}

}  // namespace cmp::fit
