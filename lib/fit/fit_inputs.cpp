#include "fit/fit_inputs.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace cmp::fit {

int resolve_column(const Rows& rows, const std::string& given, const std::vector<std::string>& defaults,
                   const std::string& flag, const std::string& model) {
  if (!given.empty()) return rows.column(given, flag);
  for (const auto& d : defaults)
    if (rows.find(d) >= 0) return rows.find(d);
  std::vector<std::string> others(defaults.begin() + 1, defaults.end());
  return rows.column(defaults.front(),
                     fmt::format("{}the default {} of model {}; name one with {}",
                                 others.empty() ? "" : fmt::format("nor '{}': ", fmt::join(others, "', '")), flag,
                                 model, flag));
}

Loss choose_loss(const std::string& option, const Model& model, const Rows& rows,
                 const std::vector<std::size_t>& selected, int y) {
  bool binary = true;
  for (std::size_t i : selected) binary = binary && (rows.number(i, y) == 0 || rows.number(i, y) == 1);
  return option == "auto" ? (model.probability && binary ? Loss::MaxLikelihood : Loss::Linear) : parse_loss(option);
}

void check_outcomes(const Model& model, const Rows& rows, const std::vector<std::size_t>& selected, int y) {
  const std::string& name = rows.header[y];
  const bool outcomes = std::find(model.outcome_columns.begin(), model.outcome_columns.end(), name) !=
                        model.outcome_columns.end();
  if (!outcomes && !model.probability) return;
  for (std::size_t i : selected) {
    const double v = rows.number(i, y);
    if (outcomes && v != 0 && v != 1)
      throw InputError(rows.files[rows.source[i]], rows.lines[i],
                       fmt::format("{} holds 0/1 outcomes (model {}), got {}", name, model.name, io::format_number(v)));
    if (!(v >= 0 && v <= 1))
      throw InputError(rows.files[rows.source[i]], rows.lines[i],
                       fmt::format("{} must lie in [0, 1] for model {} (a probability), got {}", name, model.name,
                                   io::format_number(v)));
  }
}

int sigma_column(const Rows& rows, const std::string& option, Loss loss, const std::string& y_name) {
  if (!option.empty() && option != "none") return rows.column(option, "--sigma");
  if (option.empty() && loss == Loss::Linear) return rows.find(y_name + "_error");
  return -1;
}

std::vector<std::string> mixed_systems(const Rows& rows, const std::vector<std::size_t>& selected, int x, int y) {
  std::vector<std::string> messages;
  for (const char* c : {"delta", "particles"}) {
    const int k = rows.find(c);
    if (k < 0 || k == x || k == y) continue;
    const auto v = distinct_values(rows, selected, k);
    if (v.size() > 1)
      messages.push_back(fmt::format("the data hold {} values of {} ({} ... {}), fitted as one set; "
                                     "fit each with --group-by {} or --where {}=VALUE",
                                     v.size(), c, io::format_number(v.front()), io::format_number(v.back()), c, c));
  }
  return messages;
}

}  // namespace cmp::fit
