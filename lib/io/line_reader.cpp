#include "io/line_reader.hpp"

#include "core/errors.hpp"

#include <cerrno>
#include <cstring>
#include <iostream>
#include <sys/stat.h>

namespace cmp::io {

namespace {
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trim_left(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  return s.substr(i);
}
}  // namespace

std::vector<std::string_view> split_whitespace(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

std::string quote_token(std::string_view token) {
  constexpr std::size_t kMax = 40;
  if (token.size() <= kMax) return "'" + std::string(token) + "'";
  return "'" + std::string(token.substr(0, kMax)) + "...'";
}

LineReader::LineReader(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    in_ = &std::cin;
    return;
  }
  // ifstream opens a folder without complaint and then reads nothing: say what it is instead.
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0)
    throw InputError(path_, 0, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path_, 0, "cannot open: Is a directory");
  errno = 0;
  file_.open(path_, std::ios::binary);
  if (!file_) {
    const int err = errno;
    throw InputError(path_, 0,
                     std::string("cannot open: ") + (err ? std::strerror(err) : "unknown error"));
  }
  in_ = &file_;
}

bool LineReader::next() {
  tokens_valid_ = false;
  if (!std::getline(*in_, line_)) {
    if (in_->bad()) fail("read error");
    line_.clear();
    return false;
  }
  ++line_number_;
  if (!line_.empty() && line_.back() == '\r') line_.pop_back();  // files from Windows
  if (!seen_content_ && !blank()) seen_content_ = true;
  return true;
}

bool LineReader::next_content() {
  while (next())
    if (!blank() && !comment()) return true;
  return false;
}

const std::vector<std::string_view>& LineReader::tokens() {
  if (!tokens_valid_) {
    tokens_ = split_whitespace(line_);
    tokens_valid_ = true;
  }
  return tokens_;
}

bool LineReader::blank() const {
  return trim_left(line_).empty();
}

bool LineReader::comment() const {
  const auto rest = trim_left(line_);
  return !rest.empty() && rest.front() == '#';
}

void LineReader::fail(const std::string& what) const {
  throw InputError(path_, line_number_, what);
}

void LineReader::fail_end(const std::string& expected) const {
  if (!seen_content_) throw InputError(path_, 0, "empty file");
  throw InputError(path_, line_number_, "unexpected end of file: " + expected);
}

}  // namespace cmp::io
