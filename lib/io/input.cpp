#include "io/input.hpp"

#include "core/errors.hpp"
#include "io/line_reader.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <sys/stat.h>

namespace cmp::io {

// A read buffer over a source stream buffer that can look ahead (peek) without consuming,
// and counts the bytes taken from the source (for bytes_left()).
class Input::Buffer : public std::streambuf {
 public:
  explicit Buffer(std::streambuf* source) : source_(source) { setg(nullptr, nullptr, nullptr); }

  // At least want unread bytes buffered, or all there are up to the end of the source.
  std::string_view peek(std::size_t want) {
    const auto have = static_cast<std::size_t>(egptr() - gptr());
    if (have < want && !at_end_) {
      std::string kept(gptr(), have);
      while (kept.size() < want) {
        const auto old = kept.size();
        kept.resize(want);
        const auto n = pull(kept.data() + old, want - old);
        kept.resize(old + n);
        if (n == 0) break;
      }
      data_ = std::move(kept);
      setg(data_.data(), data_.data(), data_.data() + data_.size());
    }
    return {gptr(), static_cast<std::size_t>(egptr() - gptr())};
  }

  // The bytes up to the next '\n' (not kept) into line, scanning the buffer a chunk at a
  // time. end: nothing was left; too_long: more than max bytes before the line break.
  Input::LineRead read_line(std::string& line, std::size_t max) {
    line.clear();
    bool any = false;
    while (true) {
      if (gptr() == egptr() && underflow() == traits_type::eof())
        return any ? Input::LineRead::line : Input::LineRead::end;
      any = true;
      char* begin = gptr();
      char* newline = static_cast<char*>(std::memchr(begin, '\n', static_cast<std::size_t>(egptr() - begin)));
      char* stop = newline ? newline : egptr();
      if (line.size() + static_cast<std::size_t>(stop - begin) > max) return Input::LineRead::too_long;
      line.append(begin, stop);
      setg(eback(), newline ? newline + 1 : egptr(), egptr());
      if (newline) return Input::LineRead::line;
    }
  }

  std::uint64_t pulled() const { return pulled_; }
  std::uint64_t buffered() const { return static_cast<std::uint64_t>(egptr() - gptr()); }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (at_end_) return traits_type::eof();
    data_.resize(kChunk);
    const auto n = pull(data_.data(), kChunk);
    data_.resize(n);
    setg(data_.data(), data_.data(), data_.data() + n);
    return n ? traits_type::to_int_type(*gptr()) : traits_type::eof();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 16;

  std::size_t pull(char* into, std::size_t n) {
    const auto got = source_->sgetn(into, static_cast<std::streamsize>(n));
    if (got <= 0) {
      at_end_ = true;
      return 0;
    }
    pulled_ += static_cast<std::uint64_t>(got);
    return static_cast<std::size_t>(got);
  }

  std::streambuf* source_;
  std::string data_;
  std::uint64_t pulled_ = 0;
  bool at_end_ = false;
};

namespace {

// What the first lines of an input tell: the format, or nothing yet when head (not the whole
// input: complete is false) ends before the line that tells.
struct Classified {
  std::optional<InputFormat> format;
  long line = 0;          // the line that told (0: the input ended first)
  std::string_view text;  // that line
};

Classified classify(std::string_view head, bool complete) {
  std::size_t at = 0;
  long number = 0;
  while (at < head.size()) {
    const auto eol = head.find('\n', at);
    if (eol == std::string_view::npos && !complete) return {};
    const auto line = head.substr(at, eol == std::string_view::npos ? head.size() - at : eol - at);
    at = eol == std::string_view::npos ? head.size() : eol + 1;
    ++number;
    const auto told = [&](InputFormat f) { return Classified{f, number, line}; };
    if (number == 1 && line.starts_with("# vtk DataFile Version")) return told(InputFormat::vtk);
    const auto tokens = split_whitespace(line);
    if (tokens.empty() || tokens[0].front() == '#') continue;
    auto word = tokens[0];
    if (const auto hash = word.find('#'); hash != std::string_view::npos) word = word.substr(0, hash);
    if (word.ends_with("OFF")) return told(InputFormat::off);
    long long count = 0;
    if (tokens.size() == 1 && try_parse_integer(tokens[0], count) && count >= 0)
      return told(InputFormat::xyz);
    if (line.find(',') != std::string_view::npos) return told(InputFormat::csv);
    return told(InputFormat::unknown);
  }
  if (!complete) return {};
  return {InputFormat::unknown, 0, {}};
}

}  // namespace

const char* format_name(InputFormat format) {
  switch (format) {
    case InputFormat::off:
      return "OFF";
    case InputFormat::xyz:
      return "extended XYZ";
    case InputFormat::vtk:
      return "VTK";
    case InputFormat::csv:
      return "CSV";
    default:
      return "unknown";
  }
}

InputFormat detect_format(std::string_view head) {
  return *classify(head, true).format;
}

Input::Input(std::string path) : path_(std::move(path)), stream_(nullptr) {
  if (path_ == "-") {
    buffer_ = std::make_unique<Buffer>(std::cin.rdbuf());
  } else {
    // ifstream opens a folder without complaint and then reads nothing: say what it is.
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
    if (S_ISREG(st.st_mode)) file_size_ = static_cast<std::uint64_t>(st.st_size);
    buffer_ = std::make_unique<Buffer>(file_.rdbuf());
  }
  stream_.rdbuf(buffer_.get());
}

Input::Input(std::string name, std::istream& source)
    : path_(std::move(name)), buffer_(std::make_unique<Buffer>(source.rdbuf())), stream_(nullptr) {
  stream_.rdbuf(buffer_.get());
}

Input::~Input() = default;

InputFormat Input::format() {
  if (format_known_) return format_;
  std::size_t want = 4096;
  while (true) {
    const auto head = buffer_->peek(want);
    const bool complete = head.size() < want;  // the whole input is buffered
    const auto c = classify(head, complete || want >= kMaxHeadBytes);
    if (c.format) {
      format_ = *c.format;
      format_line_ = c.line;
      // A line running past the head: too long for any reader.
      head_too_long_ = c.line > 0 && c.text.size() >= kMaxLineBytes;
      format_text_ = std::string(c.text.substr(0, 256));
      break;
    }
    want = std::min(2 * want, kMaxHeadBytes);
  }
  format_known_ = true;
  return format_;
}

void Input::fail_format(const std::string& expected) {
  const auto f = format();
  if (head_too_long_)
    throw InputError(path_, format_line_,
                     fmt::format("line longer than {} bytes (the limit of every reader): not a "
                                 "text file of this format?",
                                 kMaxLineBytes));
  if (format_line_ == 0) throw InputError(path_, 0, "empty file: expected " + expected);
  if (f == InputFormat::unknown)
    throw InputError(path_, format_line_,
                     "expected " + expected + ", got " + quote_token(format_text_));
  throw InputError(path_, format_line_,
                   "expected " + expected + ", the content is " + std::string(format_name(f)));
}

Input::LineRead Input::read_line(std::string& line, std::size_t max) {
  return buffer_->read_line(line, max);
}

std::optional<std::uint64_t> Input::bytes_left() const {
  if (!file_size_) return std::nullopt;
  const auto consumed = buffer_->pulled() - buffer_->buffered();
  return *file_size_ > consumed ? *file_size_ - consumed : 0;
}

}  // namespace cmp::io
