#include "fit/model_list.hpp"

#include "fit/models.hpp"

#include "core/registry.hpp"

#include <fmt/format.h>

namespace cmp::fit {

void write_model_list(std::ostream& out) {
  // The listing every tool prints (core/registry.hpp), then what a fit needs to know.
  out << "kind,name,description,formula,domain,parameters,x_columns,y_columns\n";
  for (const auto& m : models()) {
    std::vector<std::string> params;
    for (const auto& p : m.params)
      params.push_back(fmt::format("{}: {}{}", p.name, p.meaning,
                                   p.fixed_by_default ? fmt::format(" (fixed at {} unless --free {})", p.start, p.name) : ""));
    out << "model," << m.name << ',' << quoted_field(m.source) << ',' << quoted_field(m.formula) << ','
        << quoted_field(m.domain) << ',' << quoted_field(fmt::format("{}", fmt::join(params, "; "))) << ','
        << quoted_field(fmt::format("{}", fmt::join(m.x_columns, " "))) << ','
        << quoted_field(fmt::format("{}", fmt::join(m.y_columns, " "))) << '\n';
  }
}

}  // namespace cmp::fit
