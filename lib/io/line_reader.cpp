#include "io/line_reader.hpp"

#include "core/errors.hpp"
#include "io/input.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cmp::io {

namespace {
std::string_view trim_left(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_field_space(s[i])) ++i;
  return s.substr(i);
}
}  // namespace

std::vector<std::string_view> split_whitespace(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_field_space(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !is_field_space(text[i])) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

std::string quote_token(std::string_view token) {
  constexpr std::size_t kMax = 60;
  std::size_t keep = std::min(token.size(), kMax);
  // Do not cut inside a UTF-8 sequence (continuation bytes are 10xxxxxx).
  if (keep < token.size())
    while (keep > 0 && (static_cast<unsigned char>(token[keep]) & 0xC0) == 0x80) --keep;
  std::string out = "'";
  for (const char ch : token.substr(0, keep)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F) {
      out += fmt::format("\\x{:02X}", c);
    } else if (c == '\\') {
      out += "\\\\";
    } else {
      out += ch;
    }
  }
  if (keep < token.size()) out += "...";
  return out + "'";
}

LineReader::LineReader(std::string path)
    : owned_(std::make_unique<Input>(std::move(path))), input_(owned_.get()) {}

LineReader::LineReader(Input& input) : input_(&input) {}

LineReader::~LineReader() = default;

const std::string& LineReader::path() const {
  return input_->path();
}

std::istream& LineReader::stream() {
  return input_->stream();
}

bool LineReader::next() {
  tokens_valid_ = false;
  const auto got = input_->read_line(line_, kMaxLineBytes);
  if (got == Input::LineRead::end) return false;
  ++line_number_;
  if (got == Input::LineRead::too_long)
    fail(fmt::format("line longer than {} bytes (the limit of every reader): not a text file "
                     "of this format?",
                     kMaxLineBytes));
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
  throw InputError(path(), line_number_, what);
}

void LineReader::fail_end(const std::string& expected) const {
  if (!seen_content_) throw InputError(path(), 0, "empty file");
  throw InputError(path(), line_number_, "unexpected end of file: " + expected);
}

}  // namespace cmp::io
