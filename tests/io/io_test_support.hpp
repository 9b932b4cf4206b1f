#pragma once
// Shared helpers of the lib/io tests: a scratch folder, file contents, bitwise comparison and
// catching the cmp::InputError a reader should throw.
#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace cmp::io::test {

// A fresh folder under $TMPDIR, removed with everything in it at the end of the test.
class TempDir {
 public:
  TempDir() {
    auto templ = (std::filesystem::temp_directory_path() / "cmp_io_test.XXXXXX").string();
    std::vector<char> buf(templ.begin(), templ.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed");
    path_ = buf.data();
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  // Names of everything in the folder, hidden files included, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path_))
      out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  REQUIRE(out.good());
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in.good());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
inline bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Doubles that a careless writer would not read back unchanged.
inline std::vector<double> awkward_doubles() {
  return {0.1,
          1e-300,
          1.0 / 3.0,
          -0.0,
          1e-8,
          1.0 + 1e-8,
          4.9406564584124654e-324,
          1.7976931348623157e308,
          -2.5e-310,
          123456789.12345679,
          2.0 / 3.0 * 1e-8,
          0.0,
          -7.0,
          0.30000000000000004,
          6.02214076e23};
}

// Runs f, which must throw cmp::InputError; returns its what() (fails the test otherwise).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const cmp::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    FAIL("expected cmp::InputError, got another exception: " << e.what());
  }
  FAIL("expected cmp::InputError, nothing was thrown");
  return {};
}

// A malformed file and the error it must give: "file:line: ..." containing `message`
// (line 0: "file: ..." for the file as a whole).
struct BadInputCase {
  const char* what;
  std::string text;
  long line;
  const char* message;
};

// Writes each case to `file_name` in a scratch folder, reads it with read(path), and checks
// the error's location and message; one Catch2 section per case.
template <class Read>
void check_bad_inputs(const std::vector<BadInputCase>& cases, const std::string& file_name, Read&& read) {
  TempDir dir;
  for (const auto& c : cases) {
    SECTION(c.what) {
      const auto path = dir.file(file_name);
      write_text(path, c.text);
      const auto msg = input_error([&] { read(path); });
      const auto prefix = c.line > 0 ? path + ":" + std::to_string(c.line) + ": " : path + ": ";
      CHECK_THAT(msg, Catch::Matchers::StartsWith(prefix));
      CHECK_THAT(msg, Catch::Matchers::Contains(c.message));
    }
  }
}

// Replaces std::cin / std::cout by a string buffer for the lifetime of the object.
class StdinFrom {
 public:
  explicit StdinFrom(const std::string& text) : buf_(text), old_(std::cin.rdbuf(buf_.rdbuf())) {}
  ~StdinFrom() {
    std::cin.rdbuf(old_);
    std::cin.clear();
  }

 private:
  std::istringstream buf_;
  std::streambuf* old_;
};

class StdoutTo {
 public:
  StdoutTo() : old_(std::cout.rdbuf(buf_.rdbuf())) {}
  ~StdoutTo() { std::cout.rdbuf(old_); }
  std::string text() const { return buf_.str(); }

 private:
  std::ostringstream buf_;
  std::streambuf* old_;
};

}  // namespace cmp::io::test
