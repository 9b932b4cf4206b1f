#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"

#include <catch2/catch.hpp>

using namespace cmp;

TEST_CASE("Seed ranges", "[cli]") {
  CHECK(cli::parse_seed_range("7") == std::vector<std::uint64_t>{7});
  CHECK(cli::parse_seed_range("1:4") == std::vector<std::uint64_t>{1, 2, 3, 4});
  for (const char* bad : {"", "x", "1:", ":3", "4:1", "1:2:3", "-1", "1.5", "0:1000000"})
    CHECK_THROWS_AS(cli::parse_seed_range(bad), UsageError);
}

TEST_CASE("Output patterns", "[cli]") {
  CHECK(cli::expand_pattern("cell_{seed}.off", "seed", "7") == "cell_7.off");
  CHECK(cli::expand_pattern("{seed}/{seed}.off", "seed", "12") == "12/12.off");
  CHECK(cli::expand_pattern("plain.off", "seed", "7") == "plain.off");
}

TEST_CASE("Command lines are quoted for provenance", "[cli]") {
  const char* args[] = {"/usr/bin/rndmesh", "random", "-o", "my mesh.off"};
  CHECK(cli::command_line(4, const_cast<char**>(args)) == "rndmesh random -o 'my mesh.off'");
}

TEST_CASE("run_tool maps errors to exit statuses", "[cli]") {
  CHECK(cli::run_tool("t", [] { return 0; }) == 0);
  CHECK(cli::run_tool("t", []() -> int { throw UsageError("bad option"); }) == 2);
  CHECK(cli::run_tool("t", []() -> int { throw InputError("f.off", 3, "bad"); }) == 2);
  CHECK(cli::run_tool("t", []() -> int { throw ComputationError("diverged"); }) == 1);
}
