#pragma once
// The "key=value key2="quoted value" flag" comment line of extended XYZ, read the way ASE
// and OVITO read it: values may be quoted with "...", '...', {...} or [...]; a backslash
// takes the next character literally; a bare key means key=T.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cmp::io {

using KeyValues = std::vector<std::pair<std::string, std::string>>;

// Splits text into key=value pairs, in order, with quotes and escapes removed.
// Throws cmp::InputError(file, line, ...) for an unterminated quote or an empty key ("=5").
KeyValues parse_key_values(std::string_view text, const std::string& file, long line);

// "key=value", quoting the value with "..." (escaping '"' and '\') when it is empty or holds
// whitespace, a quote, a bracket, '=' or '\'. Line breaks become spaces. Throws
// std::invalid_argument when key is empty or holds whitespace, '=', a quote or a bracket.
std::string format_key_value(const std::string& key, const std::string& value);

// True when a and b are the same key up to ASCII case: extended XYZ's keys (Lattice, pbc,
// Properties) and the column names readers look for are matched this way, as ASE does.
bool same_key(std::string_view a, std::string_view b);

}  // namespace cmp::io
