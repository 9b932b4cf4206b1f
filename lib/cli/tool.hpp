#pragma once
// The command-line conventions of DESIGN.md in one place, so every program gets them alike:
// CLI11 options, --version, --seed, --threads, --quiet, exit statuses 0/1/2 and every
// message prefixed with the tool's name.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cmp::cli {

// Exit statuses (DESIGN.md).
enum ExitStatus : int { kSuccess = 0, kComputationFailed = 1, kBadInput = 2 };

// Runs body() and maps what escapes it to a message on stderr and an exit status:
// CLI11 parse errors and cmp::UsageError / cmp::InputError -> 2, cmp::ComputationError and
// anything else -> 1. Each line of a message is prefixed with "tool: ".
int run_tool(const std::string& tool, const std::function<int()>& body);

// An App with the toolkit's formatting and a --version flag ("tool <version>").
// Options and subcommands are added by the tool; parse with parse().
std::unique_ptr<CLI::App> make_app(const std::string& tool, const std::string& purpose);

// Parses argv; --help and --version print and end the program with status 0 (by throwing
// CLI::Success through run_tool); parse errors become cmp::UsageError (status 2).
void parse(CLI::App& app, int argc, char** argv);

// The options most programs share.
struct CommonOptions {
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  bool quiet = false;
};
void add_seed_option(CLI::App& app, CommonOptions& common);
void add_threads_option(CLI::App& app, CommonOptions& common);
void add_quiet_option(CLI::App& app, CommonOptions& common);
// Sets the OpenMP thread count from common.threads (0 leaves the default: all cores).
void apply_threads(const CommonOptions& common);

// Collects every problem with the options before reporting them all at once (exit 2).
class OptionChecks {
 public:
  // Records message when ok is false.
  void require(bool ok, const std::string& message);
  // Throws cmp::UsageError holding every recorded message, one per line, if there are any.
  void throw_if_any() const;
 private:
  std::vector<std::string> problems_;
};

// The command line as typed (arguments with spaces quoted), for provenance headers.
std::string command_line(int argc, char** argv);

// "tool version" followed by the command line: what every output file records of its origin.
std::string provenance(const std::string& tool, int argc, char** argv);

}  // namespace cmp::cli
