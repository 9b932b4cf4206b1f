#pragma once
// Output that appears under its final name only when complete (docs/conventions.md: writers write a
// temporary file in the target folder and rename it). "-" writes to standard output.
//
// Every temporary that exists is listed in a process-wide registry, so that an interrupted
// run can remove them from a signal handler (cli::run_tool installs one for SIGINT and
// SIGTERM). Other temporaries a tool makes (a folder for gnuplot's output, a scratch file)
// join the registry through TemporaryPath.
#include <functional>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>

namespace cmp {
class InputError;
}

namespace cmp::io {

class AtomicOutput {
 public:
  // Checks the target: "-" means stdout; a target that exists and is not a regular file (a
  // device such as /dev/null, a FIFO, bash's >(...)) is written in place, without a
  // temporary; otherwise the folder must exist and be writable.
  // The temporary "<dir>/.<name>.tmp.XXXXXX" is created at the first stream() call (so a tool
  // can open its outputs before a long computation without leaving files while it computes).
  // Throws cmp::InputError(path, 0, ...) when the folder does not exist or is not writable.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();  // removes the temporary file unless commit() succeeded
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // The stream to write; creates the temporary on the first call. Throws cmp::InputError
  // when it cannot be created.
  std::ostream& stream();
  // Flushes, checks for write errors, renames onto the final name (permissions 0644 minus
  // umask). Throws cmp::InputError(path, 0, ...) on failure and leaves no file behind. An
  // output never written commits as an empty file.
  void commit();
  const std::string& path() const { return path_; }

 private:
  void create_temporary();
  void discard();  // closes and removes the temporary, if any
  std::string path_, temp_path_;
  std::unique_ptr<std::ostream> file_;
  int registration_ = -1;
  bool committed_ = false;
  bool in_place_ = false;  // a device or pipe: no temporary, no rename
};

// The mkstemp template of path's temporary, "<dir>/.<name>.tmp.XXXXXX", the name cut so that
// the whole fits the folder's NAME_MAX (a 255-byte target's temporary would not).
std::string temporary_template(const std::string& path);

// Commits outputs in the order given (the primary result first), each even when an earlier one
// failed, so that a secondary output that cannot be written (a full disk, /dev/full) never
// discards a result already computed; null pointers are skipped. Then throws the first
// failure, saying which outputs were written all the same:
//   "/dev/full: write error: No space left on device (the other outputs were written: o.csv)".
void commit_in_order(std::initializer_list<AtomicOutput*> outputs);
// The error e with " (note)" added to its message, same file and line.
cmp::InputError with_note(const cmp::InputError& e, const std::string& note);

// Outputs written whole during the work (a VTK per run, a packing per target), whose failure
// must not throw away the table the work is building (docs/conventions.md, "The result
// first"): each write goes through attempt(), which keeps the first cmp::InputError instead of
// letting it end the run; after the work, commit_then_throw() commits the tables and only then
// throws that failure, "/dev/full: write error: No space left on device (the table was
// written: pf.csv)". (lbflow's flow_batch does the same by hand.)
//   io::SecondaryOutputs secondary;
//   for (...) { ...; table.row(...); secondary.attempt([&] { io::write_vtk(name, image, title); }); }
//   secondary.commit_then_throw({&table_out});
class SecondaryOutputs {
 public:
  SecondaryOutputs();
  ~SecondaryOutputs();  // out of line: InputError is only declared here
  SecondaryOutputs(const SecondaryOutputs&) = delete;
  SecondaryOutputs& operator=(const SecondaryOutputs&) = delete;
  // Runs write; an InputError it throws is kept (the first one) and the work goes on.
  void attempt(const std::function<void()>& write);
  bool failed() const { return first_ != nullptr; }
  long failures() const { return failures_; }
  // commit_in_order(tables); then, if a secondary output failed, throws its error with the
  // note "the table was written: NAME" (NAMES for several; "the other outputs ..." when a
  // table failed too, whose error is thrown instead).
  void commit_then_throw(std::initializer_list<AtomicOutput*> tables);

 private:
  std::unique_ptr<cmp::InputError> first_;
  long failures_ = 0;
};

// A path to remove if the process is interrupted, registered for as long as this object
// lives (it removes nothing itself when destroyed: the owner removes or renames its file).
//   io::TemporaryPath guard(".fit.png.tmp.x1y2/fit.png");  // then create the file
// Directories are removed (rmdir, so they must be empty by then) after every file, so
// register a folder first and the files in it after. At most kMaxTemporaries paths of up to
// 4095 bytes are held at once; beyond that a path is not registered (registered() is false).
class TemporaryPath {
 public:
  enum class Kind { File, Directory };
  explicit TemporaryPath(const std::string& path, Kind kind = Kind::File);
  ~TemporaryPath();
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  bool registered() const { return slot_ >= 0; }

 private:
  int slot_;
};
inline constexpr int kMaxTemporaries = 256;

// The registry itself: register_temporary returns a slot (-1 when full or the path is too
// long), unregister_temporary frees it. Thread-safe.
int register_temporary(const std::string& path, TemporaryPath::Kind kind = TemporaryPath::Kind::File);
void unregister_temporary(int slot);
// Unlinks every registered file, then rmdirs every registered folder. Async-signal-safe
// (only unlink, rmdir and atomics): meant for a signal handler, right before _exit.
void remove_registered_temporaries() noexcept;

}  // namespace cmp::io
