#include "cli/seed_range.hpp"

#include "core/errors.hpp"

#include <charconv>
#include <filesystem>

namespace cmp::cli {

bool parse_u64(const std::string& s, std::uint64_t& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

std::vector<std::uint64_t> parse_seed_range(const std::string& text, const std::string& option) {
  const auto colon = text.find(':');
  std::uint64_t first = 0, last = 0;
  const bool ok = colon == std::string::npos
                      ? parse_u64(text, first) && (last = first, true)
                      : parse_u64(text.substr(0, colon), first) && parse_u64(text.substr(colon + 1), last);
  if (!ok) throw UsageError(option + ": expected a seed or a range FIRST:LAST, got '" + text + "'");
  if (last < first) throw UsageError(option + ": empty range '" + text + "'");
  if (last - first >= 1000000) throw UsageError(option + ": more than 10^6 seeds in '" + text + "'");
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = first; s <= last; ++s) seeds.push_back(s);
  return seeds;
}

std::string expand_pattern(const std::string& pattern, const std::string& key, const std::string& value) {
  const std::string token = "{" + key + "}";
  std::string out = pattern;
  for (auto at = out.find(token); at != std::string::npos; at = out.find(token, at + value.size()))
    out.replace(at, token.size(), value);
  return out;
}

bool outputs_complete(const std::vector<std::string>& paths) {
  for (const auto& path : paths) {
    std::error_code ec;
    if (path == "-" || !std::filesystem::is_regular_file(path, ec)) return false;
  }
  return !paths.empty();
}

}  // namespace cmp::cli
