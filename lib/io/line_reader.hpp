#pragma once
// Line-by-line reading of a text file (or standard input) that remembers where it is, so every
// reader of lib/io reports problems as "file:line: what" (DESIGN.md: readers are strict).
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace cmp::io {

// The whitespace-separated tokens of text (views into text; spaces, tabs, CR, VT, FF).
std::vector<std::string_view> split_whitespace(std::string_view text);

// Shortens a token quoted in an error message, so a megabyte of junk gives a short message.
std::string quote_token(std::string_view token);

class LineReader {
 public:
  // Opens path for reading; "-" reads standard input.
  // Throws cmp::InputError(path, 0, "cannot open: <reason>") when the file cannot be read
  // (missing, a folder, no permission).
  explicit LineReader(std::string path);
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Reads the next line (without its "\n" or "\r\n") into line(); returns false at the end of
  // the file, where line_number() stays at the last line read. Throws cmp::InputError on an
  // I/O error.
  bool next();
  // Like next(), but skips lines that are blank or whose first non-blank character is '#'.
  bool next_content();

  const std::string& line() const { return line_; }
  // 1-based number of the current line; 0 before the first next().
  long line_number() const { return line_number_; }
  const std::string& path() const { return path_; }
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
  // directly bypasses the line count.
  std::istream& stream() { return *in_; }

 private:
  std::string path_;
  std::ifstream file_;
  std::istream* in_ = nullptr;
  std::string line_;
  std::vector<std::string_view> tokens_;
  bool tokens_valid_ = false;
  bool seen_content_ = false;
  long line_number_ = 0;
};

}  // namespace cmp::io
