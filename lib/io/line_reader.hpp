#pragma once
// Line-by-line reading of a text file (or standard input) that remembers where it is, so every
// reader of lib/io reports problems as "file:line: what" (readers are strict: docs/formats.md).
// Lines are at most kMaxLineBytes long: a longer one (a binary file, /dev/zero) is an error
// at its line, found after reading that many bytes, not after filling memory.
#include <cstddef>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cmp::io {

// The blanks that separate a line's fields (every reader's notion of white space; not \n).
inline bool is_field_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

class Input;

// The longest line any reader of lib/io accepts [bytes, without the line break]: 1 MiB.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

// The whitespace-separated tokens of text (views into text; spaces, tabs, CR, VT, FF).
std::vector<std::string_view> split_whitespace(std::string_view text);

// Input quoted in an error message: in single quotes, cut to 60 bytes with "..." (so a
// megabyte of junk gives a short message), control bytes, DEL and NUL shown as \xNN (so
// no terminal escape reaches the terminal) and a backslash as \\.
std::string quote_token(std::string_view token);

class LineReader {
 public:
  // Opens path for reading; "-" reads standard input.
  // Throws cmp::InputError(path, 0, "cannot open: <reason>") when the file cannot be read
  // (missing, a folder, no permission).
  explicit LineReader(std::string path);
  // Reads input (not owned; it must outlive the reader), from where it stands.
  explicit LineReader(Input& input);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Reads the next line (without its "\n" or "\r\n") into line(); returns false at the end of
  // the file, where line_number() stays at the last line read. Throws cmp::InputError on an
  // I/O error, and for a line longer than kMaxLineBytes (at that line).
  bool next();
  // Like next(), but skips lines that are blank or whose first non-blank character is '#'.
  bool next_content();

  const std::string& line() const { return line_; }
  // 1-based number of the current line; 0 before the first next().
  long line_number() const { return line_number_; }
  const std::string& path() const;
  // Tokens of the current line, split on whitespace (views into line(), valid until next()).
  const std::vector<std::string_view>& tokens();
  // True when the current line holds only whitespace.
  bool blank() const;
  // True when the current line is a comment: its first non-blank character is '#'.
  bool comment() const;

  // Throws cmp::InputError(path, line_number(), what).
  [[noreturn]] void fail(const std::string& what) const;
  // For a file that ended too soon: throws "empty file" (line 0) when no non-blank line was
  // read, else "unexpected end of file: <expected>" at the last line.
  [[noreturn]] void fail_end(const std::string& expected) const;

  // The underlying stream, for a binary payload that follows a text header (VTK). Reading it
  // directly bypasses the line count. The reader takes nothing from it beyond the line break
  // of the last line read.
  std::istream& stream();
  // The input read (for bytes_left()).
  Input& input() { return *input_; }

 private:
  std::unique_ptr<Input> owned_;
  Input* input_ = nullptr;
  std::string line_;
  std::vector<std::string_view> tokens_;
  bool tokens_valid_ = false;
  bool seen_content_ = false;
  long line_number_ = 0;
};

}  // namespace cmp::io
