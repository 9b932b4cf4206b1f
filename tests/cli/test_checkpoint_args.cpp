#include "cli/checkpoint_args.hpp"

#include <catch2/catch.hpp>

using namespace cmp::cli;

TEST_CASE("checkpoint arguments: the process-only options go, in both forms, the rest stays in order") {
  const ProcessOnlyOption only[] = {{"--threads", true}, {"--resume", true}, {"-q", false}};
  const std::vector<std::string> args{"in.vtk", "--threads", "2", "--tau", "0.8", "-q", "--resume=x.ckpt",
                                      "--threads=1", "--refine", "2", "-qq"};
  CHECK(checkpoint_arguments(args, only) == std::vector<std::string>{"in.vtk", "--tau", "0.8", "--refine", "2", "-qq"});
  CHECK(checkpoint_arguments(std::vector<std::string>{"--threads"}, only).empty());  // a value missing at the end
  CHECK(checkpoint_arguments(std::vector<std::string>{"-q=1"}, only) == std::vector<std::string>{"-q=1"});
}
