// lib/io/csv.hpp: tables with provenance lines, RFC 4180 quoting, strict reading.
#include "io/csv.hpp"

#include "io/atomic_output.hpp"
#include "io_test_support.hpp"

#include <climits>

#include <sstream>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("format_number gives the shortest round-trip form", "[csv]") {
  CHECK(format_number(0.1) == "0.1");
  CHECK(format_number(1e-8) == "1e-08");
  CHECK(format_number(3.0) == "3");
  CHECK(format_number(-0.0) == "-0");
  CHECK(format_number(1.0 / 3.0) == "0.3333333333333333");
  CHECK(format_number(std::nan("")) == "nan");
  CHECK(format_number(-INFINITY) == "-inf");
}

TEST_CASE("csv_field quotes only what needs it", "[csv]") {
  CHECK(csv_field("plain") == "plain");
  CHECK(csv_field("") == "");
  CHECK(csv_field("a,b") == "\"a,b\"");
  CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(csv_field("#not a comment") == "\"#not a comment\"");
  CHECK(csv_field(" padded") == "\" padded\"");
}

TEST_CASE("CSV round trip keeps meta, awkward names and every double", "[csv]") {
  TempDir dir;
  const auto path = dir.file("t.csv");
  const auto values = awkward_doubles();
  {
    AtomicOutput out(path);
    CsvWriter csv(out.stream());
    csv.meta("tool", "kcfit 0.1-abc");
    csv.meta("command", "kcfit flow.csv --x porosity\n--y k");
    csv.header({"i", "value", "label, with comma", "quote\"d"});
    for (std::size_t i = 0; i < values.size(); ++i)
      csv.row({std::to_string(i), format_number(values[i]), i % 2 ? "a,b" : "#x", "line\nbreak"});
    out.commit();
  }
  const auto t = read_csv(path);
  CHECK(t.file == path);
  REQUIRE(t.meta.size() == 2);
  CHECK(t.meta[0] == std::pair<std::string, std::string>("tool", "kcfit 0.1-abc"));
  CHECK(*t.find_meta("command") == "kcfit flow.csv --x porosity --y k");
  CHECK(t.find_meta("absent") == nullptr);
  CHECK(t.header == std::vector<std::string>{"i", "value", "label, with comma", "quote\"d"});
  CHECK(t.header_line == 3);
  REQUIRE(t.rows.size() == values.size());
  const int v = t.column("value");
  CHECK(v == 1);
  CHECK(t.column("label, with comma") == 2);
  for (std::size_t i = 0; i < values.size(); ++i) {
    INFO("row " << i << ": " << t.rows[i][1]);
    CHECK(same_bits(t.number(i, v), values[i]));
    CHECK(t.rows[i][2] == (i % 2 ? "a,b" : "#x"));
    CHECK(t.rows[i][3] == "line\nbreak");
    CHECK(t.row_lines[i] == 4 + 2 * static_cast<long>(i));  // each row spans two lines
  }
}

TEST_CASE("CSV reader skips blank lines and comments, keeps meta only above the header", "[csv]") {
  TempDir dir;
  const auto path = dir.file("t.csv");
  write_text(
      path,
      "# a plain comment\r\n# phi = 0.85 \r\n\r\n#seed=7\r\nx,y\r\n1, 2\r\n\r\n# k=v after\r\n"
      "3,4\r\n\"5\",\"\"\r\n");
  const auto t = read_csv(path);
  REQUIRE(t.meta.size() == 2);
  CHECK(t.meta[0] == std::pair<std::string, std::string>("phi", "0.85"));
  CHECK(t.meta[1] == std::pair<std::string, std::string>("seed", "7"));
  CHECK(t.header_line == 5);
  REQUIRE(t.rows.size() == 3);
  CHECK(t.number(0, 1) == 2.0);  // spaces around a number are fine
  CHECK(t.row_lines == std::vector<long>{6, 9, 10});
  CHECK(t.rows[2] == std::vector<std::string>{"5", ""});
}

TEST_CASE("CSV single column with an empty cell survives", "[csv]") {
  std::ostringstream s;
  CsvWriter csv(s);
  csv.header({"name"});
  csv.row({""});
  csv.row({"b"});
  CHECK(s.str() == "name\n\"\"\nb\n");
  TempDir dir;
  write_text(dir.file("t.csv"), s.str());
  const auto t = read_csv(dir.file("t.csv"));
  CHECK(t.rows == std::vector<std::vector<std::string>>{{""}, {"b"}});
}

TEST_CASE("CSV without a final line break", "[csv]") {
  TempDir dir;
  write_text(dir.file("t.csv"), "a,b\n1,\"x\"");
  CHECK(read_csv(dir.file("t.csv")).rows == std::vector<std::vector<std::string>>{{"1", "x"}});
}

TEST_CASE("CSV reads standard input for '-'", "[csv]") {
  StdinFrom in("a,b\n1,2\n");
  const auto t = read_csv("-");
  CHECK(t.number(0, t.column("b")) == 2.0);
}

TEST_CASE("CSV errors name the file and the line", "[csv]") {
  const std::vector<BadInputCase> cases = {
      {"empty file", "", 0, "empty file"},
      {"meta but no header", "# a=1\n\n", 2, "unexpected end of file: no header row"},
      {"row too short", "a,b,c\n1,2,3\n4,5\n", 3, "row has 2 fields, the header has 3"},
      {"row too long", "a,b\n1,2\n\n3,4,5\n", 4, "row has 3 fields, the header has 2"},
      {"unterminated quote", "a,b\n1,\"2\n3,4\n", 2, "unterminated quoted field"},
      {"junk after a closing quote", "a,b\n1,\"2\"x\n", 2, "unexpected 'x' after a closing quote"},
      {"quote inside an unquoted field", "a,b\n1,2\"\n", 2, "a '\"' inside an unquoted field"},
      {"duplicate column", "x,y,x\n", 1, "column 'x' appears twice in the header"},
      {"meta without key", "# =3\na\n", 1, "without a key"},
  };
  check_bad_inputs(cases, "bad.csv", [](const std::string& path) { read_csv(path); });
}

TEST_CASE("CSV column and number errors point at the header and the row", "[csv]") {
  TempDir dir;
  const auto path = dir.file("t.csv");
  write_text(path, "# tool=x\nporosity,kappa_lu\n0.5,abc\n0.6,nan\n0.7,1e999\n");
  const auto t = read_csv(path);
  CHECK(input_error([&] { t.column("permeability"); }) ==
        path + ":2: no column 'permeability'; the columns are 'porosity', 'kappa_lu'");
  CHECK(input_error([&] { t.number(0, 1); }) ==
        path + ":3: expected a number in column 'kappa_lu', got 'abc'");
  CHECK_THAT(input_error([&] { t.number(1, 1); }),
             StartsWith(path + ":4: ") && Contains("(finite)"));
  CHECK_THAT(input_error([&] { t.number(2, 1); }), StartsWith(path + ":5: "));
  CHECK(t.number(2, 0) == 0.7);
  CHECK_THROWS_AS(t.number(3, 0), std::out_of_range);
  CHECK_THROWS_AS(t.number(0, 2), std::out_of_range);
}

TEST_CASE("CSV integer cells are strict and in range and errors name file and line", "[csv]") {
  TempDir dir;
  const auto path = dir.file("t.csv");
  write_text(path, "particles,delta\n 32 ,0.05\n1e300,0.05\n2.5,0.05\n99999999999,0.05\n-1,0.05\n");
  const auto t = read_csv(path);
  CHECK(t.integer(0, 0, 1, INT_MAX) == 32);
  CHECK(input_error([&] { t.integer(1, 0, 1, INT_MAX); }) ==
        path + ":3: expected an integer in column 'particles', got '1e300'");
  CHECK_THAT(input_error([&] { t.integer(2, 0, 1, INT_MAX); }), StartsWith(path + ":4: "));
  CHECK(input_error([&] { t.integer(3, 0, 1, INT_MAX); }) ==
        path + ":5: expected an integer in column 'particles' in [1, 2147483647], got '99999999999'");
  CHECK_THAT(input_error([&] { t.integer(4, 0, 1, INT_MAX); }), StartsWith(path + ":6: "));
  CHECK_THROWS_AS(t.integer(5, 0, 1, 2), std::out_of_range);
}

TEST_CASE("CSV missing file", "[csv]") {
  TempDir dir;
  CHECK(input_error([&] { read_csv(dir.file("no.csv")); }) ==
        dir.file("no.csv") + ": cannot open: No such file or directory");
}

TEST_CASE("CsvWriter enforces the shape of a table", "[csv]") {
  std::ostringstream s;
  CsvWriter csv(s);
  CHECK_THROWS_AS(csv.row({"1"}), std::logic_error);
  CHECK_THROWS_AS(csv.meta("a=b", "1"), std::invalid_argument);
  CHECK_THROWS_AS(csv.meta("", "1"), std::invalid_argument);
  csv.meta("k", "v");
  csv.header({"a", "b"});
  CHECK_THROWS_AS(csv.header({"a", "b"}), std::logic_error);
  CHECK_THROWS_AS(csv.meta("late", "1"), std::logic_error);
  CHECK_THROWS_AS(csv.row({"1"}), std::invalid_argument);
  csv.row({"1", "2"});
  CHECK(s.str() == "# k=v\na,b\n1,2\n");
}
