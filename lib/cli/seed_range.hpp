#pragma once
// Many independent runs from one command: `--seeds 1:100` and output names with `{seed}`.
#include <cstdint>
#include <string>
#include <vector>

namespace cmp::cli {

// "7" -> {7}; "1:4" -> {1, 2, 3, 4} (inclusive). Throws cmp::UsageError naming `option`
// for anything else, an empty range, or more than 10^6 seeds.
std::vector<std::uint64_t> parse_seed_range(const std::string& text, const std::string& option = "--seeds");

// A whole string as an unsigned 64-bit integer (digits only); false for anything else.
bool parse_u64(const std::string& s, std::uint64_t& out);

// Replaces every "{key}" in pattern by value: ("cell_{seed}.off", "seed", "7") -> "cell_7.off".
std::string expand_pattern(const std::string& pattern, const std::string& key, const std::string& value);

// True when every path names an existing regular file: for --resume, a seed whose outputs all
// exist is done, since io::AtomicOutput shows a file under its name only when complete.
// "-" (stdout) is never complete.
bool outputs_complete(const std::vector<std::string>& paths);

}  // namespace cmp::cli
