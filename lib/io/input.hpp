#pragma once
// An input opened by name, for every reader of lib/io: a file, standard input for "-", or a
// stream (tests, fuzzing). Its first bytes can be looked at to tell the format from the
// content ('-' for every format, docs/formats.md) without losing them for the reader that follows.
#include <cstdint>
#include <fstream>
#include <istream>
#include <memory>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>

namespace cmp::io {

// The file formats of the toolkit, as told from their first bytes.
enum class InputFormat { unknown, off, xyz, vtk, csv };

// "OFF", "extended XYZ", "VTK", "CSV" or "unknown".
const char* format_name(InputFormat format);

// The format of a file that starts with head (its first lines):
//   VTK  the first line starts with "# vtk DataFile Version";
//   then blank lines and '#' comment lines are skipped, and the first other line tells:
//   OFF  its first word ends in "OFF" (OFF, COFF, NOFF, CNOFF, ...);
//   XYZ  it is one non-negative integer (the atom count of the first frame);
//   CSV  it holds a comma (the header row).
// unknown otherwise, or when head ends before such a line.
InputFormat detect_format(std::string_view head);

class Input {
 public:
  // The longest first part of an input looked at to tell its format [bytes].
  static constexpr std::size_t kMaxHeadBytes = std::size_t{1} << 20;

  // Opens path for reading; "-" reads standard input (std::cin's buffer). Throws
  // cmp::InputError(path, 0, "cannot open: <reason>") for a missing file, a folder or no
  // permission.
  explicit Input(std::string path);
  // Reads from source (not owned; must outlive the Input); name is used in messages.
  Input(std::string name, std::istream& source);
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;
  ~Input();

  const std::string& path() const { return path_; }
  // The bytes from the start (those looked at by format() included).
  std::istream& stream() { return stream_; }
  // The format told by detect_format from the first lines: reads up to the first line that
  // is neither blank nor a comment (at most kMaxHeadBytes), keeping them for stream().
  // Call before reading anything else.
  InputFormat format();
  // Reads the bytes up to the next '\n' (dropped) into line: LineRead::line, or end when
  // nothing is left, or too_long when more than max bytes come before the line break (they
  // are not consumed). For the line reader; mixing it with stream() is fine.
  enum class LineRead { line, end, too_long };
  LineRead read_line(std::string& line, std::size_t max);
  // Throws cmp::InputError at the line that told the format (line 0 for an empty input):
  // "expected <expected>, got '<that line>'" for an unknown format, "..., the content is CSV"
  // for a known one, "line longer than ..." when that line passes kMaxLineBytes.
  [[noreturn]] void fail_format(const std::string& expected);
  // Bytes not yet read when the input is a regular file (its size is known), else nullopt
  // (standard input, a pipe, a FIFO, a device, a stream).
  std::optional<std::uint64_t> bytes_left() const;

 private:
  class Buffer;
  std::string path_;
  std::ifstream file_;
  std::optional<std::uint64_t> file_size_;
  std::unique_ptr<Buffer> buffer_;
  std::istream stream_;
  bool format_known_ = false;
  InputFormat format_ = InputFormat::unknown;
  long format_line_ = 0;
  bool head_too_long_ = false;
  std::string format_text_;
};

}  // namespace cmp::io
