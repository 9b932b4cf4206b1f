#pragma once
// What every program of the toolkit does alike on its command line (the README's
// "Conventions of every program"), in one place: CLI11 options, --version,
// --seed/--seeds/--resume, --threads, --quiet, exit statuses 0/1/2, every message prefixed
// with the tool's name, every bad option reported at once under its flag, and SIGINT/SIGTERM
// handled (cli/interrupt.hpp).
//
// A tool's main, with cli::Tool (rndmesh, shellpack, percolate and kcfit are worked examples):
//
//   int main(int argc, char** argv) {
//     return cli::run_tool("poresize", [&] {
//       Options o;
//       cli::Tool tool("poresize", "Pore sizes of packings.");
//       auto& app = tool.app();                      // plain CLI11 for strings, flags, subcommands
//       app.add_option("packings", o.inputs, "OFF or XYZ files ('-': stdin)")->required();
//       tool.add_double(app, "--delta", o.delta, "voxel side [D0]", cli::positive());
//       tool.add_int(app, "--bins", o.bins, "histogram bins", cli::at_least(1));
//       app.add_option("--axis", o.axis, "x, y or z");
//       tool.add_common(app, o.common);              // --seed --threads --quiet (kSeed|kThreads|kQuiet)
//       tool.parse(argc, argv);                      // CLI11 errors: "tool: msg" + the --help hint, exit 2
//       tool.collect("--axis", [&] { o.flow_axis = voxel::axis_from_name("--axis", o.axis); });  // a parser's error
//       tool.check(o.bins * o.delta <= 10, "--bins", "times --delta must not exceed 10 D0");  // across options
//       tool.finish_checks();                        // every problem at once, exit 2
//       cli::apply_threads(o.common);
//       ...
//     });
//   }
//
// Numbers are bound to a string and converted strictly after parsing (io/parse_number.hpp:
// "2abc", "0x2", "nan" are refused), then range-checked, each problem recorded as
// "--flag: 'abc' is not an integer" or "--flag: must be positive, got '-1'". Help shows
// `--flag INT` or `--flag FLOAT` with the default (none for a required option). Options a
// tool parses itself (lists, names) report under their flag too, with check() or
// collect(flag, f). Every program (rndmesh, shellpack, percolate, kcfit) is built on Tool.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace cmp::cli {

// Exit statuses: 0 success, 1 the computation failed, 2 bad usage or bad input.
enum ExitStatus : int { kSuccess = 0, kComputationFailed = 1, kBadInput = 2 };

// Installs the SIGINT/SIGTERM handlers (cli/interrupt.hpp), runs body() and maps what escapes
// it to a message on stderr and an exit status: CLI11 parse errors (with a "run 'tool --help'"
// line) and cmp::UsageError / cmp::InputError -> 2, cmp::ComputationError and anything else
// -> 1. Each line of a message is prefixed with "tool: ".
int run_tool(const std::string& tool, const std::function<int()>& body);

// The options most programs share.
struct CommonOptions {
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  bool quiet = false;
};
// Sets the OpenMP thread count from common.threads (0 leaves the default: all cores).
void apply_threads(const CommonOptions& common);

// The most threads --threads accepts: kThreadsPerCore times the cores OpenMP sees, and never
// more than OpenMP's thread limit (OMP_THREAD_LIMIT). libgomp crashes (or fails "Thread
// creation failed") long before the thread counts an int can hold, so every program refuses
// more, before any work: "--threads: must lie in [0, 128] (64 per core of this machine's 2),
// got '100000'". max_threads_reason() is the parenthesis.
inline constexpr int kThreadsPerCore = 64;
int max_threads();
std::string max_threads_reason();

// The range a number option must lie in; lo/hi_open exclude the bound. Said in messages as
// "must be positive", "must be at least 4", "must lie in [1, 14]", "must lie in (0, 1)".
// reason, when given, says where a bound comes from; describe() adds it in parentheses:
// "must lie in [0, 128] (64 per core of this machine's 2)".
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  std::string reason;
  bool contains(double x) const;
  std::string describe() const;  // "must be positive", ...; "" when unbounded
  Bounds because(std::string why) const {
    Bounds b = *this;
    b.reason = std::move(why);
    return b;
  }
};
inline Bounds any_value() { return {}; }
inline Bounds positive() { return {0, std::numeric_limits<double>::infinity(), true, false, {}}; }
inline Bounds non_negative() { return {0, std::numeric_limits<double>::infinity(), false, false, {}}; }
inline Bounds at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false, {}}; }
inline Bounds closed(double lo, double hi) { return {lo, hi, false, false, {}}; }
inline Bounds open(double lo, double hi) { return {lo, hi, true, true, {}}; }
inline Bounds left_open(double lo, double hi) { return {lo, hi, true, false, {}}; }   // (lo, hi]
inline Bounds right_open(double lo, double hi) { return {lo, hi, false, true, {}}; }  // [lo, hi)

// The --seed/--seeds/--resume trio of tools that make one result per seed.
struct SeedOptions {
  std::uint64_t seed = 1;
  std::string seeds;    // FIRST:LAST, empty for a single run with `seed`
  bool resume = false;  // skip seeds whose outputs all exist (writes are atomic: they are complete)
};

// One program's command line: the App, typed number options converted strictly after
// parsing, and the list of problems reported together (see the example at the top).
class Tool {
 public:
  Tool(std::string name, std::string purpose);
  CLI::App& app() { return *app_; }
  const std::string& name() const { return name_; }

  // Number options bound to value (left unchanged when the option is not given), shown in
  // help as INT or FLOAT with value as the default. Any CLI11 calls (->required(),
  // ->excludes()) may follow on the returned option.
  CLI::Option* add_int(CLI::App& where, const std::string& flags, int& value, const std::string& help,
                       Bounds bounds = {});
  CLI::Option* add_long(CLI::App& where, const std::string& flags, long& value, const std::string& help,
                        Bounds bounds = {});
  CLI::Option* add_uint64(CLI::App& where, const std::string& flags, std::uint64_t& value, const std::string& help);
  // Doubles must be finite ("nan", "inf" refused) and within bounds.
  CLI::Option* add_double(CLI::App& where, const std::string& flags, double& value, const std::string& help,
                          Bounds bounds = {});

  // The common options; which is a bitwise or of the flags below.
  enum Common : unsigned { kSeed = 1, kThreads = 2, kQuiet = 4 };
  void add_common(CLI::App& where, CommonOptions& common, unsigned which = kSeed | kThreads | kQuiet);
  // --seed, --seeds FIRST:LAST (excludes --seed) and --resume; `what` names the result
  // ("mesh", "packing") in the help.
  void add_seed_options(CLI::App& where, SeedOptions& seeds, const std::string& what);
  // The seeds to run: {seeds.seed} or the range. A bad range is recorded as a problem of
  // --seeds (and {seed.seed} returned) so finish_checks reports it with the rest.
  std::vector<std::uint64_t> seed_list(const SeedOptions& seeds);
  // When several seeds run, every per-seed output pattern must contain {seed}: records
  // "FLAG: must contain {seed} when --seeds names several seeds, e.g. -o 'cell_{seed}.off'".
  void check_seed_pattern(std::size_t seed_count, const std::string& flag, const std::string& pattern,
                          const std::string& example);

  // An output file option ('-': stdout), bound to value like app.add_option. finish_checks()
  // checks every output declared in the (sub)command that was run, before any work
  // (io/output_paths.hpp): its folder exists and is writable, no two outputs are one file
  // (compared by device and inode, not by spelling), no output is one of the inputs declared
  // with declare_inputs; each problem under the output's flag, exit 2.
  CLI::Option* add_output(CLI::App& where, const std::string& flags, std::string& value, const std::string& help);
  // Declares an output whose option the tool adds itself (a flag taking several forms).
  void declare_output(CLI::App& where, const std::string& flag, const std::string& value);
  // The values a placeholder of the output patterns takes ("seed" -> the seeds; seed_list
  // sets it): a pattern whose folder holds it ('s{seed}/r.off') is checked in each folder.
  void set_placeholder_values(const std::string& placeholder, std::vector<std::string> values);
  // The files the (sub)command reads: no output may be one of them. The vector or string is
  // read when the checks run (after parse), so bind it as for add_option.
  void declare_inputs(CLI::App& where, const std::vector<std::string>& paths);
  void declare_input(CLI::App& where, const std::string& path);

  // Parses argv. --help/--version print and end with status 0 (CLI::Success through
  // run_tool). A CLI11 error (unknown option, missing required, extra arguments) and an
  // unknown or missing subcommand are thrown at once as cmp::UsageError with the --help hint;
  // conversion and range problems of the typed options are recorded for finish_checks().
  // With required subcommands, the first argument not starting with '-' is taken as the
  // subcommand, so top-level options must be flags (take no value).
  void parse(int argc, char** argv);
  // Records "flag: message" when ok is false (flag empty: the message alone). A flag already
  // reported (say, 'abc' is not an integer) is not reported twice.
  void check(bool ok, const std::string& flag, const std::string& message);
  // Runs f and records the cmp::UsageError it throws (a library's validate()).
  void collect(const std::function<void()>& f);
  // Runs f (a parser of the option's text) and records the cmp::UsageError it throws under
  // flag: "--axis must be x, y or z, got 'w'" becomes "--axis: must be x, y or z, got 'w'".
  void collect(const std::string& flag, const std::function<void()>& f);
  // Throws cmp::UsageError holding every recorded problem, one per line, then the hint
  // "run 'tool [sub] --help' for the options", if there are any.
  void finish_checks() const;
  std::size_t problem_count() const { return problems_.size(); }

 private:
  struct Typed {
    CLI::Option* option;
    std::string text;
    std::function<void(Tool&, const std::string& flag, const std::string& text)> convert;
  };
  CLI::Option* add_typed(CLI::App& where, const std::string& flags, const std::string& help, const std::string& type,
                         const std::string& default_text, std::function<void(Tool&, const std::string&, const std::string&)> convert);
  std::string hint() const;
  struct DeclaredOutput {
    const CLI::App* where;
    std::string flag;
    const std::string* value;
  };
  struct DeclaredInputs {
    const CLI::App* where;
    const std::vector<std::string>* paths;
    const std::string* path;
  };
  std::vector<DeclaredOutput> outputs_;
  std::map<std::string, std::vector<std::string>> placeholder_values_;
  std::vector<DeclaredInputs> inputs_;
  std::string name_;
  std::unique_ptr<CLI::App> app_;
  std::deque<Typed> typed_;  // stable addresses: CLI11 holds pointers to the strings
  std::vector<std::string> problems_;
};

// The command line as typed (arguments with spaces quoted), for provenance headers.
std::string command_line(int argc, char** argv);

// "tool version" followed by the command line: what every output file records of its origin.
std::string provenance(const std::string& tool, int argc, char** argv);
// The same for a command line held as strings (argv[0] first), e.g. without the options that
// steer only this process (cli/checkpoint_args.hpp).
std::string provenance(const std::string& tool, std::vector<std::string> args);

}  // namespace cmp::cli
