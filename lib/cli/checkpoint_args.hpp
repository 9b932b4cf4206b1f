#pragma once
// What a checkpoint records of the command line: every argument but the options that steer only
// this process (threads, quiet, progress, the resume itself), so that `--resume FILE` repeats
// the run and may change those freely. One filter for every program that checkpoints
// (shellpack compress, lbflow).
#include <span>
#include <string>
#include <vector>

namespace cmp::cli {

struct ProcessOnlyOption {
  const char* flag;  // "--threads", "-q"
  bool takes_value;  // "--threads 2" (and "--threads=2")
};

// args without the process-only options, in both their "--flag value" and "--flag=value" forms.
std::vector<std::string> checkpoint_arguments(std::span<const std::string> args,
                                              std::span<const ProcessOnlyOption> process_only);

}  // namespace cmp::cli
