#pragma once
// The container of a resumable run's checkpoint (lbflow, shellpack compress): a text header
// naming the run (the command-line arguments that define it, so `--resume FILE` alone repeats
// them), then the program's own binary state:
//   <magic line, e.g. "lbflow checkpoint 1">
//   args <n>
//   <length> <argument bytes>        (n lines)
//   state                            ("state fnv1a64" when a checksum follows the state)
//   <binary state>
//   \nfnv1a64 <16 hex digits>\n       (the checksum: 64-bit FNV-1a of the state's bytes)
// Write it with io::CheckpointOutput (atomic: a run killed while writing leaves the previous
// one; the checksum added at commit), or through io::AtomicOutput and write_checkpoint_header
// (no checksum). read_checkpoint_header verifies the checksum of a file that has one before
// a byte of the state is used: one flipped bit is "checkpoint damaged", exit 2.
#include "core/errors.hpp"
#include "core/fnv1a.hpp"
#include "io/atomic_output.hpp"

#include <cstdint>
#include <fstream>
#include <istream>
#include <ostream>
#include <streambuf>
#include <string>
#include <type_traits>
#include <vector>

namespace cmp::io {

// Writes the header up to and including the "state" line (no checksum follows).
void write_checkpoint_header(std::ostream& out, const std::string& magic, const std::vector<std::string>& args);

// A checkpoint with a checksum of its state: the header at construction, the state written to
// stream(), then commit() appends the checksum line and renames the file into place
// (io::AtomicOutput). Throws cmp::InputError(path, 0, ...) as AtomicOutput does.
class CheckpointOutput {
 public:
  CheckpointOutput(const std::string& path, const std::string& magic, const std::vector<std::string>& args);
  ~CheckpointOutput();
  CheckpointOutput(const CheckpointOutput&) = delete;
  CheckpointOutput& operator=(const CheckpointOutput&) = delete;
  std::ostream& stream() { return stream_; }
  void commit();

 private:
  // Passes bytes to the file's stream buffer and hashes them on the way.
  class HashingBuffer : public std::streambuf {
   public:
    void attach(std::streambuf* target) { target_ = target; }
    Fnv1a hash;
   protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override { return target_->pubsync(); }
   private:
    std::streambuf* target_ = nullptr;
  };
  AtomicOutput out_;
  HashingBuffer buffer_;
  std::ostream stream_;
};

// Reads the header, leaving `in` at the first byte of the state, and returns the arguments.
// Throws cmp::InputError(path, line, ...) when the first line is not `magic` ("not <what>
// (expected '<magic>' on the first line)", what e.g. "an lbflow checkpoint") or the header is
// malformed, and cmp::InputError(path, 0, "checkpoint damaged: ...") when the file has a
// checksum and the state's bytes do not match it (or it is cut short). With require_checksum,
// a file without one is refused too.
std::vector<std::string> read_checkpoint_header(std::istream& in, const std::string& path, const std::string& magic,
                                                const std::string& what, bool require_checksum = false);

// The file opened for reading in binary; cmp::InputError(path, 0, "cannot open the checkpoint").
std::ifstream open_checkpoint(const std::string& path);

// Raw native-endian bytes of trivially copyable values and vectors of them (a checkpoint is
// read back by the same build on the same machine: exact doubles, no formatting).
template <class T>
void put(std::ostream& out, const T& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
void put(std::ostream& out, const std::vector<T>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}
inline void put(std::ostream& out, const std::string& s) {
  put(out, static_cast<std::uint64_t>(s.size()));
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

// Reads what put wrote; throws cmp::InputError(path, 0, "truncated checkpoint") at the end of
// the data and for a vector longer than `max_size` elements.
class CheckpointReader {
 public:
  CheckpointReader(std::istream& in, std::string path) : in_(in), path_(std::move(path)) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    read(reinterpret_cast<char*>(&v), sizeof v);
    return v;
  }
  // Into an existing value (a type without a default constructor, e.g. a random generator).
  template <class T>
  void get_into(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    read(reinterpret_cast<char*>(&v), sizeof v);
  }
  template <class T>
  std::vector<T> get_vector(std::uint64_t max_size) {
    const auto n = get<std::uint64_t>();
    if (n > max_size) fail();
    std::vector<T> v(n);
    read(reinterpret_cast<char*>(v.data()), n * sizeof(T));
    return v;
  }
  std::string get_string(std::uint64_t max_size) {
    const auto n = get<std::uint64_t>();
    if (n > max_size) fail();
    std::string s(n, '\0');
    read(s.data(), n);
    return s;
  }
  const std::string& path() const { return path_; }

 private:
  void read(char* p, std::uint64_t n) {
    if (!in_.read(p, static_cast<std::streamsize>(n))) fail();
  }
  [[noreturn]] void fail() const { throw InputError(path_, 0, "truncated or damaged checkpoint"); }
  std::istream& in_;
  std::string path_;
};

}  // namespace cmp::io
