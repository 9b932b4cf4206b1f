#include "io/atomic_output.hpp"

#include "core/errors.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace cmp::io {

namespace {
std::string errno_text(int err) {
  return std::strerror(err);
}

// The process umask. umask() can only be read by setting it, which races with other threads
// creating files; Linux shows it in /proc/self/status, so read it there when possible.
mode_t process_umask() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "Umask:") {
      unsigned mask = 0;
      if (status >> std::oct >> mask) return static_cast<mode_t>(mask);
      break;
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  const mode_t m = ::umask(022);
  ::umask(m);
  return m;
}

const char* kStdout = "<stdout>";
}  // namespace

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  if (path_ == "-") return;
  if (path_.empty()) throw InputError(path_, 0, "cannot write: empty file name");
  const std::filesystem::path target(path_);
  const auto name = target.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(path_, 0, "cannot write: not a file name");
  const auto dir = target.parent_path();
  // Hidden, in the same folder: rename() is atomic only within one file system.
  temp_path_ = (dir / ("." + name + ".tmp.XXXXXX")).string();
  std::vector<char> templ(temp_path_.begin(), temp_path_.end());
  templ.push_back('\0');
  const int fd = ::mkstemp(templ.data());
  if (fd < 0) {
    const int err = errno;
    temp_path_.clear();
    throw InputError(path_, 0, "cannot write: " + errno_text(err));
  }
  temp_path_ = templ.data();
  // mkstemp makes the file 0600; a finished output gets the usual 0644 minus the umask.
  ::fchmod(fd, 0644 & ~process_umask());
  ::close(fd);
  auto file = std::make_unique<std::ofstream>(temp_path_, std::ios::binary | std::ios::trunc);
  if (!*file) {
    const int err = errno;
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
    throw InputError(path_, 0, "cannot write: " + errno_text(err ? err : EIO));
  }
  file_ = std::move(file);
}

AtomicOutput::~AtomicOutput() {
  if (committed_ || temp_path_.empty()) return;
  file_.reset();  // close before unlinking
  ::unlink(temp_path_.c_str());
}

std::ostream& AtomicOutput::stream() {
  if (path_ == "-") return std::cout;
  return *file_;
}

void AtomicOutput::commit() {
  if (committed_) return;
  if (path_ == "-") {
    std::cout.flush();
    if (!std::cout) throw InputError(kStdout, 0, "write error");
    committed_ = true;
    return;
  }
  auto& file = static_cast<std::ofstream&>(*file_);
  file.flush();
  const bool written = static_cast<bool>(file);
  errno = 0;
  file.close();
  const int close_err = errno;
  if (!written || file.fail()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
    throw InputError(path_, 0, "write error: " + errno_text(close_err ? close_err : EIO));
  }
  // No fsync: the promise is about interrupted runs, not power cuts, and fsync per file would
  // slow sweeps that write thousands of small files.
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
    throw InputError(path_, 0, "cannot write: " + errno_text(err));
  }
  committed_ = true;
}

}  // namespace cmp::io
