#include "cli/checkpoint_args.hpp"

namespace cmp::cli {

std::vector<std::string> checkpoint_arguments(std::span<const std::string> args,
                                              std::span<const ProcessOnlyOption> process_only) {
  std::vector<std::string> kept;
  for (std::size_t k = 0; k < args.size(); ++k) {
    bool skip = false;
    for (const ProcessOnlyOption& o : process_only) {
      const std::string flag = o.flag;
      if (args[k] == flag) {
        skip = true;
        if (o.takes_value) ++k;
        break;
      }
      if (o.takes_value && args[k].starts_with(flag + "=")) {
        skip = true;
        break;
      }
    }
    if (!skip) kept.push_back(args[k]);
  }
  return kept;
}

}  // namespace cmp::cli
