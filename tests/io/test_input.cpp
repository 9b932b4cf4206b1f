// lib/io/input.hpp and lib/io/line_reader.hpp: the format told from the content, the bytes
// looked at kept for the reader, the line-length limit and quoting of input in messages.
#include "io/input.hpp"

#include "io/csv.hpp"
#include "io/line_reader.hpp"
#include "io/off.hpp"
#include "io/xyz.hpp"

#include "io_test_support.hpp"

#include <sstream>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("detect_format tells OFF and extended XYZ and VTK and CSV from their first lines", "[input]") {
  CHECK(detect_format("OFF\n3 1 0\n") == InputFormat::off);
  CHECK(detect_format("# made by hand\n\nCOFF 3 1 0\n") == InputFormat::off);
  CHECK(detect_format("OFF# comment\n") == InputFormat::off);
  CHECK(detect_format("NOFF\n") == InputFormat::off);
  CHECK(detect_format("20\nLattice=\"1 0 0 0 1 0 0 0 1\"\n") == InputFormat::xyz);
  CHECK(detect_format("  3  \r\n\n") == InputFormat::xyz);
  CHECK(detect_format("# vtk DataFile Version 3.0\ntitle\n") == InputFormat::vtk);
  CHECK(detect_format("# provenance=x\nfile,delta\n1,2\n") == InputFormat::csv);
  CHECK(detect_format("") == InputFormat::unknown);
  CHECK(detect_format("\n# only comments\n") == InputFormat::unknown);
  CHECK(detect_format("PLY\n") == InputFormat::unknown);
  CHECK(detect_format("-3\n") == InputFormat::unknown);
  CHECK(std::string(format_name(InputFormat::xyz)) == "extended XYZ");
}

TEST_CASE("Input keeps the bytes it looked at for the reader that follows", "[input]") {
  const std::string off = "# c\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  SECTION("standard input") {
    StdinFrom in(off);
    Input input("-");
    CHECK(input.format() == InputFormat::off);
    CHECK_FALSE(input.bytes_left());
    const auto m = read_off(input);
    CHECK(m.V.rows() == 3);
    CHECK(m.F.rows() == 1);
  }
  SECTION("a regular file: bytes_left counts down") {
    TempDir dir;
    write_text(dir.file("a.off"), off);
    Input input(dir.file("a.off"));
    CHECK(input.bytes_left() == off.size());
    CHECK(input.format() == InputFormat::off);
    CHECK(input.bytes_left() == off.size());  // looking consumed nothing
    CHECK(read_off(input).V.rows() == 3);
    CHECK(input.bytes_left() == 0u);
  }
  SECTION("a stream, and a first line longer than the first look") {
    const std::string csv = "# note=" + std::string(10000, 'x') + "\na,b\n1,2\n";
    std::istringstream s(csv);
    Input input("mem", s);
    CHECK(input.format() == InputFormat::csv);
    const auto t = read_csv(input);
    CHECK(t.header == std::vector<std::string>{"a", "b"});
    CHECK(t.meta[0].second.size() == 10000);
  }
}

TEST_CASE("a line longer than the limit is an error at its line and not a memory hog", "[input]") {
  TempDir dir;
  SECTION("no line break at all (as /dev/zero)") {
    write_text(dir.file("z.xyz"), std::string(kMaxLineBytes + 10, '\0'));
    const auto msg = input_error([&] { read_xyz(dir.file("z.xyz")); });
    CHECK_THAT(msg, StartsWith(dir.file("z.xyz") + ":1: line longer than 1048576 bytes"));
  }
  SECTION("a long line after good ones") {
    write_text(dir.file("l.csv"), "a,b\n1,2\n" + std::string(kMaxLineBytes + 1, '7') + "\n");
    CHECK_THAT(input_error([&] { read_csv(dir.file("l.csv")); }),
               StartsWith(dir.file("l.csv") + ":3: line longer than"));
  }
  SECTION("a line of exactly the limit is read") {
    write_text(dir.file("ok.csv"), "a\n" + std::string(kMaxLineBytes, '7') + "\n");
    CHECK(read_csv(dir.file("ok.csv")).rows[0][0].size() == kMaxLineBytes);
  }
  SECTION("a quoted CSV field running over many lines") {
    std::string text = "a\n\"";
    for (int i = 0; i < 1100; ++i) text += std::string(1000, 'q') + "\n";
    write_text(dir.file("q.csv"), text);
    CHECK_THAT(input_error([&] { read_csv(dir.file("q.csv")); }),
               StartsWith(dir.file("q.csv") + ":2: quoted field longer than"));
  }
}

TEST_CASE("input quoted in messages is cut and escaped", "[input]") {
  CHECK(quote_token("abc") == "'abc'");
  CHECK(quote_token(std::string(100, 'a')) == "'" + std::string(60, 'a') + "...'");
  CHECK(quote_token(std::string("a\x1b[31mb\0c", 9)) == "'a\\x1B[31mb\\x00c'");
  CHECK(quote_token("tab\there\x7f") == "'tab\\x09here\\x7F'");
  CHECK(quote_token("back\\slash") == "'back\\\\slash'");
  // not cut inside a UTF-8 character: 59 ASCII bytes then a 2-byte character
  const std::string utf8 = std::string(59, 'a') + "\xc3\xa9" + "zzz";
  CHECK(quote_token(utf8) == "'" + std::string(59, 'a') + "...'");
  // a whole message stays short however long the junk
  TempDir dir;
  write_text(dir.file("j.xyz"), std::string(500000, 'j') + "\x1b[2J\n");
  const auto msg = input_error([&] { read_xyz(dir.file("j.xyz")); });
  CHECK(msg.size() < 200);
  CHECK(msg.find('\x1b') == std::string::npos);
}
