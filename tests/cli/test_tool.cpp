#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "io/atomic_output.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <iterator>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace cmp;
using Catch::Matchers::Contains;

namespace {
// Parses args (without the program name) with tool and returns the UsageError's text ("" when
// parsing and every check passed).
std::string usage_error(cli::Tool& tool, std::vector<std::string> args) {
  args.insert(args.begin(), tool.name());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  try {
    tool.parse(static_cast<int>(argv.size()), argv.data());
    tool.finish_checks();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

struct Jam {
  int spheres = 0;
  double pmin = 1e-8, dt = 0.1, youngs = 1;
  int level = 1;
  cli::Tool tool{"pack", "test tool"};
  CLI::App* jam = nullptr;
  Jam() {
    tool.app().require_subcommand(1);
    jam = tool.app().add_subcommand("jam", "jam");
    tool.add_int(*jam, "-N,--spheres", spheres, "number of spheres")->required();
    tool.add_double(*jam, "--pmin", pmin, "P_min", cli::positive());
    tool.add_double(*jam, "--fire-dt", dt, "dt", cli::positive());
    tool.add_double(*jam, "--youngs-modulus", youngs, "E", cli::positive());
    tool.add_int(*jam, "--level", level, "level", cli::closed(1, 14));
    tool.app().add_subcommand("structure", "structure");
  }
};
}  // namespace

TEST_CASE("Tool reports every bad option at once under its flag name", "[cli]") {
  Jam j;
  const auto msg = usage_error(j.tool, {"jam", "-N", "20", "--pmin", "-1", "--fire-dt", "-1", "--youngs-modulus", "-3"});
  CHECK(msg ==
        "--pmin: must be positive, got '-1'\n"
        "--fire-dt: must be positive, got '-1'\n"
        "--youngs-modulus: must be positive, got '-3'\n"
        "run 'pack jam --help' for the options");
  CHECK(j.spheres == 20);
}

TEST_CASE("Tool converts numbers strictly and says what was expected", "[cli]") {
  Jam j;
  CHECK_THAT(usage_error(j.tool, {"jam", "-N", "20", "--level", "abc"}), Contains("--level: 'abc' is not an integer"));
  Jam k;
  CHECK_THAT(usage_error(k.tool, {"jam", "-N", "2x"}), Contains("--spheres: '2x' is not an integer"));
  Jam l;
  CHECK_THAT(usage_error(l.tool, {"jam", "-N", "20", "--pmin", "0x2", "--level", "0"}),
             Contains("--pmin: '0x2' is not a finite number\n--level: must lie in [1, 14], got '0'"));
  Jam m;
  CHECK_THAT(usage_error(m.tool, {"jam", "-N", "20", "--pmin", "nan"}), Contains("--pmin: 'nan' is not a finite number"));
  Jam ok;
  CHECK(usage_error(ok.tool, {"jam", "-N", "20", "--pmin", "2e-8", "--level", "14"}).empty());
  CHECK(ok.pmin == 2e-8);
  CHECK(ok.level == 14);
}

TEST_CASE("Tool names an unknown subcommand and lists the real ones", "[cli]") {
  Jam j;
  CHECK(usage_error(j.tool, {"foo"}) ==
        "unknown subcommand 'foo'; the subcommands are jam, structure\nrun 'pack --help' for the options");
  Jam k;
  CHECK_THAT(usage_error(k.tool, {}), Contains("a subcommand is required: one of jam, structure"));
}

TEST_CASE("Tool passes CLI11 parse errors on with the help hint", "[cli]") {
  Jam j;
  const auto unknown = usage_error(j.tool, {"jam", "-N", "20", "--no-such-option"});
  CHECK_THAT(unknown, Contains("--no-such-option"));
  CHECK_THAT(unknown, Contains("run 'pack jam --help' for the options"));
  Jam k;
  CHECK_THAT(usage_error(k.tool, {"jam"}), Contains("--spheres is required"));
}

TEST_CASE("Tool help shows the type and the default and no default for a required option", "[cli]") {
  Jam j;
  std::vector<std::string> args{"pack", "jam", "--help"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  try {
    j.tool.parse(3, argv.data());
  } catch (const CLI::Success&) {
  }
  const auto help = j.jam->help();
  CHECK_THAT(help, Contains("-N,--spheres INT REQUIRED"));
  CHECK_THAT(help, Contains("--pmin FLOAT=1e-08"));
}

TEST_CASE("Tool seed options check patterns and ranges with the other options", "[cli]") {
  cli::Tool tool("mesh", "test");
  cli::SeedOptions seeds;
  std::string output = "out.off";
  double radius = 1;
  tool.add_seed_options(tool.app(), seeds, "mesh");
  tool.add_double(tool.app(), "--radius", radius, "radius", cli::positive());
  std::vector<std::string> args{"mesh", "--seeds", "1:3", "--radius", "0"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  tool.parse(static_cast<int>(argv.size()), argv.data());
  const auto list = tool.seed_list(seeds);
  CHECK(list == std::vector<std::uint64_t>{1, 2, 3});
  tool.check_seed_pattern(list.size(), "-o", output, "cell_{seed}.off");
  try {
    tool.finish_checks();
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK(std::string(e.what()) ==
          "--radius: must be positive, got '0'\n"
          "-o: must contain {seed} when --seeds names several seeds, e.g. -o 'cell_{seed}.off'\n"
          "run 'mesh --help' for the options");
  }
}

TEST_CASE("Tool records a parser's error under the flag it parses", "[cli]") {
  cli::Tool tool("perc", "test");
  std::string axis = "x", marking = "faces";
  int bins = 10;
  tool.app().add_option("--axis", axis, "axis");
  tool.add_int(tool.app(), "--bins", bins, "bins", cli::at_least(1));
  std::vector<std::string> args{"perc", "--axis", "w", "--bins", "abc"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  tool.parse(static_cast<int>(argv.size()), argv.data());
  tool.collect("--axis", [&] { throw UsageError("--axis must be x, y or z, got '" + axis + "'"); });
  tool.collect("--model", [&] { throw UsageError("--model: unknown model 'kozeny'"); });
  tool.collect("--marking", [&] { throw UsageError("must be 'vertices' or 'triangles', got '" + marking + "'"); });
  tool.collect("--bins", [&] { throw UsageError("--bins: reported twice"); });
  tool.collect("--scale", [] {});
  try {
    tool.finish_checks();
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK(std::string(e.what()) ==
          "--bins: 'abc' is not an integer\n"
          "--axis: must be x, y or z, got 'w'\n"
          "--model: unknown model 'kozeny'\n"
          "--marking: must be 'vertices' or 'triangles', got 'faces'\n"
          "run 'perc --help' for the options");
  }
}

TEST_CASE("Resume counts a seed done when every output exists", "[cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "cmp_test_resume";
  std::filesystem::create_directories(dir);
  const auto a = (dir / "a.off").string(), b = (dir / "b.csv").string();
  std::filesystem::remove(a);
  std::filesystem::remove(b);
  std::ofstream(a) << "x";
  CHECK_FALSE(cli::outputs_complete({a, b}));
  std::ofstream(b) << "y";
  CHECK(cli::outputs_complete({a, b}));
  CHECK_FALSE(cli::outputs_complete({a, "-"}));
  CHECK_FALSE(cli::outputs_complete({dir.string()}));  // a folder is no output
  std::filesystem::remove_all(dir);
}

TEST_CASE("Bounds say what they require", "[cli]") {
  CHECK(cli::positive().describe() == "must be positive");
  CHECK(cli::non_negative().describe() == "must not be negative");
  CHECK(cli::at_least(4).describe() == "must be at least 4");
  CHECK(cli::open(0, 1).describe() == "must lie in (0, 1)");
  CHECK(cli::left_open(0, 1).describe() == "must lie in (0, 1]");
  CHECK(cli::positive().contains(1e-300));
  CHECK_FALSE(cli::positive().contains(0));
  CHECK(cli::any_value().describe().empty());
}

TEST_CASE("An interrupted tool removes its temporaries and exits 130 or 143", "[cli]") {
  // A real signal, in a child, while an io::AtomicOutput temporary is open.
  for (const int sig : {SIGINT, SIGTERM}) {
    const auto dir = std::filesystem::temp_directory_path() / ("cmp_test_interrupt_" + std::to_string(sig));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto err = (dir / "stderr.txt").string();
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, STDERR_FILENO);
      const int status = cli::run_tool("demo", [&] {
        io::AtomicOutput out((dir / "table.csv").string());
        out.stream() << "half a table\n";
        out.stream().flush();
        ::raise(sig);
        return 0;
      });
      ::_exit(status == 0 ? 3 : 4);  // not reached: the handler exits
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 128 + sig);
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) left.push_back(e.path().filename().string());
    CHECK(left == std::vector<std::string>{"stderr.txt"});
    std::ifstream in(err);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text == "demo: interrupted\n");
    std::filesystem::remove_all(dir);
  }
}
