#include "core/errors.hpp"

#include <new>

namespace cmp {

namespace {
std::string located(const std::string& file, long line, const std::string& what) {
  const std::string name = file == "-" ? "<stdin>" : file;
  if (line > 0) return name + ":" + std::to_string(line) + ": " + what;
  return name + ": " + what;
}
}  // namespace

InputError::InputError(std::string file, long line, const std::string& what)
    : std::runtime_error(located(file, line, what)), file_(std::move(file)), line_(line) {}

FailureReport failure_report(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return {false, "out of memory"};
  return {dynamic_cast<const UsageError*>(&e) || dynamic_cast<const InputError*>(&e), e.what()};
}

}  // namespace cmp
