#pragma once
// Tables of named styles: shell terms, contact laws, collision models, fit models, benchmark
// cases. A table is any range of entries with `name` and `description` fields (const char* or
// std::string); looking an entry up and listing a table go through here, so that every tool
// words an unknown name the same way and every `--list-models` prints the same CSV:
//
//   kind,name,description
//   contact,hertz,"V = (2/5) k delta^(5/2) ..."
//
// A new style is its own file plus one line in its kind's table.
#include "core/errors.hpp"

#include <ostream>
#include <string>
#include <string_view>

namespace cmp {

// "a, b, c": the names of a table's entries, in its order.
template <class Table>
std::string style_names(const Table& table) {
  std::string names;
  for (const auto& entry : table) {
    if (!names.empty()) names += ", ";
    names += std::string_view(entry.name);
  }
  return names;
}

// The entry called `name`; throws cmp::UsageError "unknown <kind> '<name>' (known: a, b)".
template <class Table>
const auto& find_style(const Table& table, std::string_view name, std::string_view kind) {
  for (const auto& entry : table)
    if (std::string_view(entry.name) == name) return entry;
  throw UsageError("unknown " + std::string(kind) + " '" + std::string(name) + "' (known: " + style_names(table) +
                   ")");
}

// The header of a --list-models listing.
inline void write_style_header(std::ostream& out) { out << "kind,name,description\n"; }

// A CSV field in double quotes, its own quotes doubled.
inline std::string quoted_field(std::string_view text) {
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// One CSV row per entry: kind,name,"description".
template <class Table>
void write_styles(std::ostream& out, std::string_view kind, const Table& table) {
  for (const auto& entry : table)
    out << kind << ',' << std::string_view(entry.name) << ',' << quoted_field(entry.description) << '\n';
}

}  // namespace cmp
