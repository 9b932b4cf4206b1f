#pragma once
// Output that appears under its final name only when complete (DESIGN.md: writers write a
// temporary file in the target folder and rename it). "-" writes to standard output.
#include <memory>
#include <ostream>
#include <string>

namespace cmp::io {

class AtomicOutput {
 public:
  // Creates "<dir>/.<name>.tmp.XXXXXX" next to path (or uses stdout for "-").
  // Throws cmp::InputError(path, 0, ...) when the folder does not exist or is not writable.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();  // removes the temporary file unless commit() succeeded
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ostream& stream();
  // Flushes, checks for write errors, renames onto the final name (permissions 0644 minus
  // umask). Throws cmp::InputError(path, 0, ...) on failure and leaves no file behind.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_, temp_path_;
  std::unique_ptr<std::ostream> file_;
  bool committed_ = false;
};

}  // namespace cmp::io
