#include "io/atomic_output.hpp"

#include "core/errors.hpp"
#include "io/output_paths.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <pthread.h>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
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

// The registry: fixed slots, so that a signal handler can walk it without locks or allocation.
// state: 0 free, 1 being filled, 2 a file, 3 a folder.
struct Slot {
  std::atomic<int> state{0};
  char path[4096];
};
Slot g_slots[kMaxTemporaries];

// Blocks SIGINT and SIGTERM in this thread while a temporary is created and registered, so
// that an interrupt cannot fall between the two and leave the file behind.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
 private:
  sigset_t old_;
};
}  // namespace

int register_temporary(const std::string& path, TemporaryPath::Kind kind) {
  if (path.empty() || path.size() >= sizeof(Slot::path)) return -1;
  for (int k = 0; k < kMaxTemporaries; ++k) {
    int expected = 0;
    if (!g_slots[k].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slots[k].path, path.c_str(), path.size() + 1);
    g_slots[k].state.store(kind == TemporaryPath::Kind::File ? 2 : 3);
    return k;
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0 && slot < kMaxTemporaries) g_slots[slot].state.store(0);
}

void remove_registered_temporaries() noexcept {
  for (auto& slot : g_slots)
    if (slot.state.load() == 2) ::unlink(slot.path);
  for (int k = kMaxTemporaries - 1; k >= 0; --k)
    if (g_slots[k].state.load() == 3) ::rmdir(g_slots[k].path);
}

TemporaryPath::TemporaryPath(const std::string& path, Kind kind) : slot_(register_temporary(path, kind)) {}
TemporaryPath::~TemporaryPath() { unregister_temporary(slot_); }

std::string temporary_template(const std::string& path) {
  const std::filesystem::path target(path);
  std::string name = target.filename().string();
  // ".<name>.tmp.XXXXXX" is 12 bytes longer than the name: cut the name (at a UTF-8 character's
  // start) so that the temporary fits the folder's NAME_MAX whenever the target does. mkstemp
  // makes it unique; the name only says what it is for.
  const std::string folder = target.parent_path().empty() ? "." : target.parent_path().string();
  const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::size_t name_max = limit > 0 ? static_cast<std::size_t>(limit) : 255;
  constexpr std::size_t kExtra = 12;  // "." and ".tmp.XXXXXX"
  if (name.size() + kExtra > name_max) {
    std::size_t keep = name_max > kExtra ? name_max - kExtra : 0;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    name.resize(keep);
  }
  return (target.parent_path() / ("." + name + ".tmp.XXXXXX")).string();
}

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  // Throws when the target cannot be written (io/output_paths.hpp: the check every program
  // also makes on all its outputs before any work).
  check_writable(path_);
  if (path_ == "-") return;
  // A device, pipe or socket (/dev/null, /dev/stdout, a FIFO, bash's >(...) as /dev/fd/63) is
  // written in place: renaming a finished temporary onto it would replace /dev/null by a
  // regular file (as root) or fail, and a stream has no half-written state to hide anyway.
  struct stat existing {};
  in_place_ = ::stat(path_.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode);
}

void AtomicOutput::create_temporary() {
  if (in_place_) {
    auto file = std::make_unique<std::ofstream>(path_, std::ios::binary);
    if (!*file) throw InputError(path_, 0, "cannot write: " + errno_text(errno ? errno : EIO));
    file_ = std::move(file);
    return;
  }
  // Hidden, in the same folder: rename() is atomic only within one file system.
  const std::string templ_text = temporary_template(path_);
  std::vector<char> templ(templ_text.begin(), templ_text.end());
  templ.push_back('\0');
  SignalsBlocked blocked;
  const int fd = ::mkstemp(templ.data());
  if (fd < 0) throw InputError(path_, 0, "cannot write: " + errno_text(errno));
  temp_path_ = templ.data();
  registration_ = register_temporary(temp_path_);
  // mkstemp makes the file 0600; a finished output gets the usual 0644 minus the umask.
  ::fchmod(fd, 0644 & ~process_umask());
  ::close(fd);
  auto file = std::make_unique<std::ofstream>(temp_path_, std::ios::binary | std::ios::trunc);
  if (!*file) {
    const int err = errno;
    discard();
    throw InputError(path_, 0, "cannot write: " + errno_text(err ? err : EIO));
  }
  file_ = std::move(file);
}

void AtomicOutput::discard() {
  file_.reset();  // close before unlinking
  if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
  temp_path_.clear();
  unregister_temporary(registration_);
  registration_ = -1;
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) discard();
}

std::ostream& AtomicOutput::stream() {
  if (path_ == "-") return std::cout;
  if (!file_) create_temporary();
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
  if (!file_) create_temporary();
  auto& file = static_cast<std::ofstream&>(*file_);
  file.flush();
  const bool written = static_cast<bool>(file);
  errno = 0;
  file.close();
  const int close_err = errno;
  if (!written || file.fail()) {
    discard();
    throw InputError(path_, 0, "write error: " + errno_text(close_err ? close_err : EIO));
  }
  if (in_place_) {
    committed_ = true;
    return;
  }
  // No fsync: the promise is about interrupted runs, not power cuts, and fsync per file would
  // slow sweeps that write thousands of small files.
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    discard();
    throw InputError(path_, 0, "cannot write: " + errno_text(err));
  }
  unregister_temporary(registration_);
  registration_ = -1;
  temp_path_.clear();
  committed_ = true;
}

void commit_in_order(std::initializer_list<AtomicOutput*> outputs) {
  std::optional<InputError> first;
  std::string written;
  for (auto* out : outputs) {
    if (!out) continue;
    try {
      out->commit();
      written += (written.empty() ? "" : ", ") + (out->path() == "-" ? std::string("<stdout>") : out->path());
    } catch (const InputError& e) {
      if (!first) first = e;
    }
  }
  if (!first) return;
  if (written.empty()) throw *first;
  throw with_note(*first, "the other outputs were written: " + written);
}

SecondaryOutputs::SecondaryOutputs() = default;
SecondaryOutputs::~SecondaryOutputs() = default;

void SecondaryOutputs::attempt(const std::function<void()>& write) {
  try {
    write();
  } catch (const InputError& e) {
    ++failures_;
    if (!first_) first_ = std::make_unique<InputError>(e);
  }
}

void SecondaryOutputs::commit_then_throw(std::initializer_list<AtomicOutput*> tables) {
  commit_in_order(tables);  // a table that cannot be written is the first thing to say
  if (!first_) return;
  std::string written;
  long count = 0;
  for (const auto* t : tables)
    if (t) written += (count++ ? ", " : "") + (t->path() == "-" ? std::string("<stdout>") : t->path());
  std::string note;
  if (count > 0) note = (count == 1 ? "the table was written: " : "the tables were written: ") + written;
  if (failures_ > 1)
    note += (note.empty() ? "" : "; ") + std::to_string(failures_ - 1) +
            (failures_ == 2 ? " more output failed" : " more outputs failed");
  if (note.empty()) throw *first_;
  throw with_note(*first_, note);
}

InputError with_note(const InputError& e, const std::string& note) {
  // The message without its "file:line: " prefix, which the new error adds again.
  const std::string located = e.what();
  const std::size_t prefix = std::string(InputError(e.file(), e.line(), "").what()).size();
  return InputError(e.file(), e.line(), located.substr(prefix) + " (" + note + ")");
}

}  // namespace cmp::io
