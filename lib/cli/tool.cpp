#include "cli/tool.hpp"

#include "cli/interrupt.hpp"
#include "cli/seed_range.hpp"
#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/output_paths.hpp"
#include "io/parse_number.hpp"
#include "core/version.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
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
  install_interrupt_handlers(tool);
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

void apply_threads(const CommonOptions& common) {
  if (common.threads > 0) omp_set_num_threads(std::min(common.threads, max_threads()));
}

int max_threads() {
  const long per_cores = static_cast<long>(kThreadsPerCore) * std::max(1, omp_get_num_procs());
  return static_cast<int>(std::max(1L, std::min<long>(per_cores, omp_get_thread_limit())));
}

std::string max_threads_reason() {
  const int procs = std::max(1, omp_get_num_procs());
  const long per_cores = static_cast<long>(kThreadsPerCore) * procs;
  if (omp_get_thread_limit() < per_cores) return fmt::format("OpenMP's thread limit, OMP_THREAD_LIMIT={}", omp_get_thread_limit());
  return fmt::format("{} per core of this machine's {}", kThreadsPerCore, procs);
}

bool Bounds::contains(double x) const {
  return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
}

std::string Bounds::describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  const auto num = [](double x) { return io::format_number(x); };
  std::string text;
  if (has_lo && has_hi)
    text = fmt::format("must lie in {}{}, {}{}", lo_open ? "(" : "[", num(lo), num(hi), hi_open ? ")" : "]");
  else if (has_lo && lo == 0) text = lo_open ? "must be positive" : "must not be negative";
  else if (has_lo) text = lo_open ? "must exceed " + num(lo) : "must be at least " + num(lo);
  else if (has_hi) text = hi_open ? "must be below " + num(hi) : "must be at most " + num(hi);
  if (!text.empty() && !reason.empty()) text += " (" + reason + ")";
  return text;
}

namespace {
// "--spheres" of "-N,--spheres": the name messages use.
std::string flag_name(const std::string& flags) {
  std::string first, token;
  std::istringstream in(flags);
  while (std::getline(in, token, ',')) {
    if (token.rfind("--", 0) == 0) return token;
    if (first.empty()) first = token;
  }
  return first;
}

void record_range(Tool& tool, const std::string& flag, const std::string& text, double x, const Bounds& b) {
  tool.check(b.contains(x), flag, b.describe() + ", got '" + text + "'");
}

// An App with the toolkit's formatting and a --version flag ("tool <version>").
std::unique_ptr<CLI::App> make_app(const std::string& tool, const std::string& purpose) {
  auto app = std::make_unique<CLI::App>(purpose, tool);
  app->set_version_flag("--version", tool + " " + version());
  app->set_help_all_flag("--help-all", "Print this help and that of every subcommand, then exit");
  app->get_formatter()->column_width(34);
  app->option_defaults()->always_capture_default();
  return app;
}
}  // namespace

Tool::Tool(std::string name, std::string purpose) : name_(std::move(name)), app_(make_app(name_, purpose)) {}

CLI::Option* Tool::add_typed(CLI::App& where, const std::string& flags, const std::string& help,
                             const std::string& type, const std::string& default_text,
                             std::function<void(Tool&, const std::string&, const std::string&)> convert) {
  typed_.push_back({nullptr, std::string(), std::move(convert)});
  auto& t = typed_.back();
  t.option = where.add_option(flags, t.text, help)
                 ->type_name(type)
                 ->default_str(default_text)
                 ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // the last one given wins
  return t.option;
}

CLI::Option* Tool::add_int(CLI::App& where, const std::string& flags, int& value, const std::string& help,
                           Bounds bounds) {
  return add_typed(where, flags, help, "INT", std::to_string(value),
                   [&value, bounds](Tool& tool, const std::string& flag, const std::string& text) {
                     long long v = 0;
                     if (!io::try_parse_integer(text, v) || v < INT_MIN || v > INT_MAX)
                       return tool.check(false, flag, "'" + text + "' is not an integer");
                     value = static_cast<int>(v);
                     record_range(tool, flag, text, static_cast<double>(v), bounds);
                   });
}

CLI::Option* Tool::add_long(CLI::App& where, const std::string& flags, long& value, const std::string& help,
                            Bounds bounds) {
  return add_typed(where, flags, help, "INT", std::to_string(value),
                   [&value, bounds](Tool& tool, const std::string& flag, const std::string& text) {
                     long long v = 0;
                     if (!io::try_parse_integer(text, v) || v < LONG_MIN || v > LONG_MAX)
                       return tool.check(false, flag, "'" + text + "' is not an integer");
                     value = static_cast<long>(v);
                     record_range(tool, flag, text, static_cast<double>(v), bounds);
                   });
}

CLI::Option* Tool::add_uint64(CLI::App& where, const std::string& flags, std::uint64_t& value,
                              const std::string& help) {
  return add_typed(where, flags, help, "UINT", std::to_string(value),
                   [&value](Tool& tool, const std::string& flag, const std::string& text) {
                     std::uint64_t v = 0;
                     if (!parse_u64(text, v))
                       return tool.check(false, flag, "'" + text + "' is not a non-negative integer");
                     value = v;
                   });
}

CLI::Option* Tool::add_double(CLI::App& where, const std::string& flags, double& value, const std::string& help,
                              Bounds bounds) {
  return add_typed(where, flags, help, "FLOAT", io::format_number(value),
                   [&value, bounds](Tool& tool, const std::string& flag, const std::string& text) {
                     double v = 0;
                     if (!io::try_parse_double(text, v))
                       return tool.check(false, flag, "'" + text + "' is not a finite number");
                     value = v;
                     record_range(tool, flag, text, v, bounds);
                   });
}

void Tool::add_common(CLI::App& where, CommonOptions& common, unsigned which) {
  if (which & kSeed)
    add_uint64(where, "--seed", common.seed, "seed of the random number generator; same seed, same output");
  if (which & kThreads)
    add_int(where, "--threads", common.threads,
            fmt::format("OpenMP threads (0: all cores; at most {} per core); results do not depend on it",
                        kThreadsPerCore),
            closed(0, max_threads()).because(max_threads_reason()));
  if (which & kQuiet) where.add_flag("-q,--quiet", common.quiet, "no progress bar or summary on stderr");
}

void Tool::add_seed_options(CLI::App& where, SeedOptions& seeds, const std::string& what) {
  auto* seed = add_uint64(where, "--seed", seeds.seed,
                          "seed of the random number generator; same seed, same " + what);
  where.add_option("--seeds", seeds.seeds, "FIRST:LAST: one " + what + " per seed, in parallel; outputs need {seed}")
      ->type_name("FIRST:LAST")
      ->excludes(seed);
  where.add_flag("--resume", seeds.resume,
                 "skip the seeds whose outputs all exist already (files appear only when complete)");
}

std::vector<std::uint64_t> Tool::seed_list(const SeedOptions& seeds) {
  std::vector<std::uint64_t> list{seeds.seed};
  if (!seeds.seeds.empty()) try {
      list = parse_seed_range(seeds.seeds, "--seeds");
    } catch (const UsageError& e) {
      check(false, "", e.what());
    }
  std::vector<std::string> names;
  for (auto s : list) names.push_back(std::to_string(s));
  set_placeholder_values("seed", std::move(names));
  return list;
}

void Tool::set_placeholder_values(const std::string& placeholder, std::vector<std::string> values) {
  placeholder_values_[placeholder] = std::move(values);
}

void Tool::check_seed_pattern(std::size_t seed_count, const std::string& flag, const std::string& pattern,
                              const std::string& example) {
  check(seed_count <= 1 || pattern.find("{seed}") != std::string::npos, flag,
        "must contain {seed} when --seeds names several seeds, e.g. " + flag + " '" + example + "'");
}

std::string Tool::hint() const {
  std::string command = name_;
  for (const auto* sub : app_->get_subcommands()) command += " " + sub->get_name();
  return "run '" + command + " --help' for the options";
}

void Tool::parse(int argc, char** argv) {
  // Help shows no default for a required option ("-N,--spheres INT REQUIRED").
  for (auto& t : typed_)
    if (t.option->get_required()) t.option->default_str("");
  // A subcommand that does not exist: say so and name the real ones (CLI11 would say "A
  // subcommand is required" or "arguments were not expected").
  const auto subs = app_->get_subcommands([](const CLI::App*) { return true; });
  if (!subs.empty() && app_->get_require_subcommand_min() > 0) {
    std::string names;
    for (const auto* sub : subs) names += (names.empty() ? "" : ", ") + sub->get_name();
    bool asks_help = false;
    const char* first = nullptr;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h" || arg == "--help-all" || arg == "--version") asks_help = true;
      if (arg == "--") break;
      if (!arg.empty() && arg[0] == '-') continue;
      first = argv[i];
      break;
    }
    bool known = false;
    for (const auto* sub : subs) known = known || (first && sub->check_name(first));
    if (first && !known)
      throw UsageError("unknown subcommand '" + std::string(first) + "'; the subcommands are " + names + "\n" +
                       hint());
    if (!first && !asks_help)
      throw UsageError("a subcommand is required: one of " + names + "\n" + hint());
  }
  try {
    app_->parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    app_->exit(e);
    throw CLI::Success();
  } catch (const CLI::CallForAllHelp& e) {
    app_->exit(e);
    throw CLI::Success();
  } catch (const CLI::CallForVersion& e) {
    app_->exit(e);
    throw CLI::Success();
  } catch (const CLI::ParseError& e) {
    throw UsageError(std::string(e.what()) + "\n" + hint());
  }
  for (auto& t : typed_)
    if (t.option->count() > 0) t.convert(*this, flag_name(t.option->get_name(false, true)), t.text);
}

void Tool::check(bool ok, const std::string& flag, const std::string& message) {
  if (ok) return;
  if (!flag.empty()) {  // one problem per flag: a value that did not convert is not range-checked too
    for (const auto& p : problems_)
      if (p.rfind(flag + ": ", 0) == 0) return;
    problems_.push_back(flag + ": " + message);
  } else {
    problems_.push_back(message);
  }
}

void Tool::collect(const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    std::istringstream lines(e.what());
    std::string line;
    while (std::getline(lines, line)) problems_.push_back(line);
  }
}

void Tool::collect(const std::string& flag, const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    std::string message = e.what();
    message = message.substr(0, message.find('\n'));
    for (const auto& prefix : {flag + ": ", flag + " "})
      if (message.rfind(prefix, 0) == 0) {
        message = message.substr(prefix.size());
        break;
      }
    check(false, flag, message);
  }
}

CLI::Option* Tool::add_output(CLI::App& where, const std::string& flags, std::string& value, const std::string& help) {
  auto* option = where.add_option(flags, value, help);
  outputs_.push_back({&where, flag_name(flags), &value});
  return option;
}

void Tool::declare_output(CLI::App& where, const std::string& flag, const std::string& value) {
  outputs_.push_back({&where, flag, &value});
}

void Tool::declare_inputs(CLI::App& where, const std::vector<std::string>& paths) {
  inputs_.push_back({&where, &paths, nullptr});
}

void Tool::declare_input(CLI::App& where, const std::string& path) { inputs_.push_back({&where, nullptr, &path}); }

namespace {
// The (sub)command that runs: the deepest App named on the command line (the top-level App
// when no subcommand was named).
bool ran(const CLI::App* app) {
  if (app->get_parent() != nullptr && !app->parsed()) return false;
  for (const auto* sub : app->get_subcommands([](const CLI::App*) { return true; }))
    if (sub->parsed()) return false;
  return true;
}
}  // namespace

void Tool::finish_checks() const {
  auto problems = problems_;
  std::vector<io::OutputPath> outputs;
  for (const auto& o : outputs_)
    if (ran(o.where)) outputs.push_back({o.flag, *o.value});
  std::vector<std::string> inputs;
  for (const auto& i : inputs_) {
    if (!ran(i.where)) continue;
    if (i.paths) inputs.insert(inputs.end(), i.paths->begin(), i.paths->end());
    if (i.path) inputs.push_back(*i.path);
  }
  for (const auto& p : io::output_path_problems(outputs, inputs, placeholder_values_)) {
    bool reported = false;  // one problem per flag
    for (const auto& q : problems) reported = reported || q.rfind(p.flag + ": ", 0) == 0;
    if (!reported) problems.push_back(p.flag + ": " + p.message);
  }
  if (problems.empty()) {
    announce_work_started();
    return;
  }
  std::string all;
  for (const auto& p : problems) all += p + "\n";
  throw UsageError(all + hint());
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

std::string provenance(const std::string& tool, std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return provenance(tool, static_cast<int>(argv.size()), argv.data());
}

}  // namespace cmp::cli
