#include "cli/tool.hpp"

#include "core/errors.hpp"
#include "core/version.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <iostream>
#include <sstream>

namespace cmp::cli {

namespace {
void print_prefixed(const std::string& tool, const std::string& message) {
  std::istringstream lines(message);
  std::string line;
  while (std::getline(lines, line)) std::cerr << tool << ": " << line << '\n';
}
}  // namespace

int run_tool(const std::string& tool, const std::function<int()>& body) {
  try {
    return body();
  } catch (const CLI::Success&) {
    return kSuccess;
  } catch (const CLI::ParseError& e) {
    print_prefixed(tool, e.what());
    std::cerr << tool << ": run '" << tool << " --help' for the options\n";
    return kBadInput;
  } catch (const UsageError& e) {
    print_prefixed(tool, e.what());
    return kBadInput;
  } catch (const InputError& e) {
    print_prefixed(tool, e.what());
    return kBadInput;
  } catch (const ComputationError& e) {
    print_prefixed(tool, e.what());
    return kComputationFailed;
  } catch (const std::bad_alloc&) {
    print_prefixed(tool, "out of memory");
    return kComputationFailed;
  } catch (const std::exception& e) {
    print_prefixed(tool, std::string("internal error: ") + e.what());
    return kComputationFailed;
  }
}

std::unique_ptr<CLI::App> make_app(const std::string& tool, const std::string& purpose) {
  auto app = std::make_unique<CLI::App>(purpose, tool);
  app->set_version_flag("--version", tool + " " + version());
  app->set_help_all_flag("--help-all", "Print this help and that of every subcommand, then exit");
  app->get_formatter()->column_width(34);
  app->option_defaults()->always_capture_default();
  return app;
}

void parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    app.exit(e);  // prints the help of the (sub)command that was asked
    throw CLI::Success();
  } catch (const CLI::CallForAllHelp& e) {
    app.exit(e);
    throw CLI::Success();
  } catch (const CLI::CallForVersion& e) {
    app.exit(e);
    throw CLI::Success();
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
}

void add_seed_option(CLI::App& app, CommonOptions& common) {
  app.add_option("--seed", common.seed, "seed of the random number generator; same seed, same output");
}

void add_threads_option(CLI::App& app, CommonOptions& common) {
  app.add_option("--threads", common.threads, "OpenMP threads (0: all cores); results do not depend on it")
      ->check(CLI::NonNegativeNumber);
}

void add_quiet_option(CLI::App& app, CommonOptions& common) {
  app.add_flag("-q,--quiet", common.quiet, "no progress bar or summary on stderr");
}

void apply_threads(const CommonOptions& common) {
  if (common.threads > 0) omp_set_num_threads(common.threads);
}

void OptionChecks::require(bool ok, const std::string& message) {
  if (!ok) problems_.push_back(message);
}

void OptionChecks::throw_if_any() const {
  if (problems_.empty()) return;
  std::string all;
  for (const auto& p : problems_) all += (all.empty() ? "" : "\n") + p;
  throw UsageError(all);
}

std::string command_line(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (i == 0) {  // program name without its folder
      auto slash = arg.find_last_of('/');
      if (slash != std::string::npos) arg = arg.substr(slash + 1);
    }
    const bool quote = arg.empty() || arg.find_first_of(" \t'\"$*?;&|<>()") != std::string::npos;
    if (!line.empty()) line += ' ';
    line += quote ? "'" + arg + "'" : arg;
  }
  return line;
}

std::string provenance(const std::string& tool, int argc, char** argv) {
  return fmt::format("{} {}: {}", tool, version(), command_line(argc, argv));
}

}  // namespace cmp::cli
