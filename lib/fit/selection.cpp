#include "fit/selection.hpp"

#include "core/errors.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace cmp::fit {

namespace {

std::string column_list(const std::vector<std::string>& header) {
  std::string s;
  for (const auto& h : header) s += (s.empty() ? "" : ", ") + h;
  return s;
}

// The value rounded to 12 significant digits: the identity of a group.
double group_value(double x) {
  double r = 0;
  io::try_parse_double(fmt::format("{:.12g}", x), r);
  return r;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

int Rows::find(const std::string& name) const {
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == name) return static_cast<int>(c);
  return -1;
}

int Rows::column(const std::string& name, const std::string& what) const {
  const int c = find(name);
  if (c < 0)
    throw InputError(files.empty() ? "" : files[0], header_line,
                     fmt::format("no column '{}'{}; columns: {}", name, what.empty() ? "" : " (" + what + ")",
                                 column_list(header)));
  return c;
}

double Rows::number(std::size_t row, int column) const {
  const std::string cell = trimmed(cells.at(row).at(static_cast<std::size_t>(column)));
  double v = 0;
  if (!io::try_parse_double(cell, v))
    throw InputError(files[source[row]], lines[row],
                     fmt::format("column '{}': expected a number, got '{}'", header[column], cell));
  return v;
}

Rows merge_tables(const std::vector<io::CsvTable>& tables) {
  if (tables.empty()) throw std::invalid_argument("merge_tables: no table");
  Rows r;
  r.header = tables[0].header;
  r.meta = tables[0].meta;
  r.header_line = tables[0].header_line;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const auto& table = tables[t];
    if (table.header != r.header)
      throw InputError(table.file, table.header_line,
                       fmt::format("columns differ from those of {} (every input needs the same columns in the same "
                                   "order): {} against {}",
                                   tables[0].file, column_list(table.header), column_list(r.header)));
    r.files.push_back(table.file);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      r.cells.push_back(table.rows[i]);
      r.source.push_back(t);
      r.lines.push_back(table.row_lines[i]);
    }
  }
  return r;
}

Condition parse_condition(const std::string& text) {
  const auto at = text.find_first_of("=!<>");
  if (at == std::string::npos || at == 0)
    throw UsageError(fmt::format("--where: expected column=value (or !=, <, <=, >, >=), e.g. --where delta=0.04; "
                                 "got '{}'",
                                 text));
  Condition c;
  c.text = text;
  c.column = trimmed(text.substr(0, at));
  std::string op = text.substr(at, 2);
  if (op == "==" || op == "!=" || op == "<=" || op == ">=") {
    c.op = op == "==" ? Compare::Equal : op == "!=" ? Compare::NotEqual : op == "<=" ? Compare::LessEqual : Compare::GreaterEqual;
  } else {
    op = text.substr(at, 1);
    if (op == "!")
      throw UsageError(fmt::format("--where: expected column=value (or !=, <, <=, >, >=); got '{}'", text));
    c.op = op == "=" ? Compare::Equal : op == "<" ? Compare::Less : Compare::Greater;
  }
  const std::string value = trimmed(text.substr(at + op.size()));
  if (!io::try_parse_double(value, c.value))
    throw UsageError(fmt::format("--where {}: the value '{}' is not a number", text, value));
  return c;
}

bool satisfies(const Condition& c, double x) {
  const double tol = 1e-9 * std::max(std::abs(x), std::abs(c.value));
  const bool equal = std::abs(x - c.value) <= tol;
  switch (c.op) {
    case Compare::Equal: return equal;
    case Compare::NotEqual: return !equal;
    case Compare::Less: return x < c.value && !equal;
    case Compare::LessEqual: return x < c.value || equal;
    case Compare::Greater: return x > c.value && !equal;
    case Compare::GreaterEqual: return x > c.value || equal;
  }
  return false;
}

std::vector<std::size_t> select_rows(const Rows& rows, const std::vector<Condition>& conditions) {
  std::vector<int> columns;
  for (const auto& c : conditions) columns.push_back(rows.column(c.column, "--where " + c.text));
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < rows.cells.size(); ++i) {
    bool ok = true;
    for (std::size_t k = 0; k < conditions.size() && ok; ++k) ok = satisfies(conditions[k], rows.number(i, columns[k]));
    if (ok) kept.push_back(i);
  }
  return kept;
}

std::vector<Group> group_rows(const Rows& rows, const std::vector<std::size_t>& selected,
                              const std::vector<int>& columns) {
  std::map<std::vector<double>, std::vector<std::size_t>> groups;
  for (std::size_t i : selected) {
    std::vector<double> key;
    for (int c : columns) key.push_back(group_value(rows.number(i, c)));
    groups[key].push_back(i);
  }
  std::vector<Group> out;
  for (auto& [key, members] : groups) out.push_back({key, std::move(members)});
  return out;
}

std::vector<double> distinct_values(const Rows& rows, const std::vector<std::size_t>& selected, int column) {
  std::vector<double> v;
  for (std::size_t i : selected) v.push_back(group_value(rows.number(i, column)));
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace cmp::fit
