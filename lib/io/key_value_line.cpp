#include "io/key_value_line.hpp"

#include "core/errors.hpp"
#include "io/line_reader.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace cmp::io {

namespace {
char closing(char open) {
  switch (open) {
    case '"':
      return '"';
    case '\'':
      return '\'';
    case '{':
      return '}';
    case '[':
      return ']';
    default:
      return 0;
  }
}
}  // namespace

KeyValues parse_key_values(std::string_view text, const std::string& file, long line) {
  KeyValues out;
  std::string key, value;
  bool in_value = false, any = false;  // any: the current pair has started
  char close = 0;
  const auto finish = [&] {
    if (!any) return;
    if (key.empty()) throw InputError(file, line, quote_token("=" + value) + " without a key");
    out.emplace_back(std::move(key), in_value ? std::move(value) : std::string("T"));
    key.clear(), value.clear();
    in_value = any = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    std::string& target = in_value ? value : key;
    if (c == '\\' && i + 1 < text.size()) {
      target += text[++i];
      any = true;
    } else if (close) {
      if (c == close)
        close = 0;
      else
        target += c;
    } else if (closing(c)) {
      close = closing(c);
      any = true;
    } else if (is_field_space(c)) {
      finish();
    } else if (c == '=' && !in_value) {
      in_value = any = true;
    } else {
      target += c;
      any = true;
    }
  }
  if (close)
    throw InputError(file, line, std::string("unterminated quote: no closing '") + close + "'");
  finish();
  return out;
}

std::string format_key_value(const std::string& key, const std::string& value) {
  if (key.empty() || key.find_first_of(" \t\r\n\"'={}[]\\") != std::string::npos)
    throw std::invalid_argument("extended XYZ: bad key '" + key + "'");
  const bool quote = value.empty() || value.find_first_of(" \t\r\n\"'={}[]\\") != std::string::npos;
  if (!quote) return key + '=' + value;
  std::string out = key + "=\"";
  for (char c : value) {
    if (c == '\n' || c == '\r') c = ' ';
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

bool same_key(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace cmp::io
