#pragma once
// The three ways a run can fail, mapped by cli::run_tool to the exit statuses of docs/conventions.md:
//   InputError       a malformed or unreadable input file      -> exit 2, "tool: file:line: what"
//   UsageError       a bad option value or combination          -> exit 2, "tool: what"
//   ComputationError the input was fine but the computation failed -> exit 1, "tool: what"
#include <stdexcept>
#include <string>

namespace cmp {

class InputError : public std::runtime_error {
 public:
  // line = 0 when the problem is the file as a whole (missing, empty, unreadable).
  InputError(std::string file, long line, const std::string& what);
  const std::string& file() const { return file_; }
  long line() const { return line_; }

 private:
  std::string file_;
  long line_;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ComputationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How a failure caught as std::exception is told on: bad input (InputError, UsageError: exit 2)
// or not (exit 1), and its message, "out of memory" for std::bad_alloc. (lbm's agree and
// lbflow's abort path; cli::run_tool catches each kind itself, to print each its way.)
struct FailureReport {
  bool bad_input = false;
  std::string message;
};
FailureReport failure_report(const std::exception& e);

}  // namespace cmp
