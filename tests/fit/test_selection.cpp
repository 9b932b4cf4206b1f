// Several CSV tables read as one, rows kept by conditions and split into groups
// (lib/fit/selection.hpp): what kcfit's --where and --group-by do.
#include "core/errors.hpp"
#include "fit/selection.hpp"

#include <catch2/catch.hpp>

using namespace cmp;

namespace {

io::CsvTable table(const std::string& file, std::vector<std::string> header, std::vector<std::vector<std::string>> rows) {
  io::CsvTable t;
  t.file = file;
  t.header = std::move(header);
  t.header_line = 2;
  for (std::size_t i = 0; i < rows.size(); ++i) t.row_lines.push_back(static_cast<long>(3 + i));
  t.rows = std::move(rows);
  return t;
}

}  // namespace

TEST_CASE("tables with the same columns merge and each row keeps its file and line", "[fit]") {
  const auto a = table("a.csv", {"delta", "y"}, {{"0.04", "1"}, {"0.05", "2"}});
  const auto b = table("b.csv", {"delta", "y"}, {{"0.040", "abc"}});
  const auto rows = fit::merge_tables({a, b});
  REQUIRE(rows.cells.size() == 3);
  CHECK(rows.files[rows.source[2]] == "b.csv");
  CHECK(rows.lines[2] == 3);
  CHECK(rows.number(1, 1) == 2);
  CHECK_THROWS_WITH(rows.number(2, 1), Catch::Contains("b.csv:3") && Catch::Contains("'abc'"));
  CHECK_THROWS_WITH(rows.column("phi", "--x"), Catch::Contains("a.csv:2") && Catch::Contains("no column 'phi'") &&
                                                    Catch::Contains("delta, y"));
  const auto c = table("c.csv", {"y", "delta"}, {{"1", "0.04"}});
  CHECK_THROWS_WITH(fit::merge_tables({a, c}), Catch::Contains("c.csv:2") && Catch::Contains("columns differ"));
}

TEST_CASE("conditions compare numbers with a tolerance for their formatting", "[fit]") {
  const auto eq = fit::parse_condition("delta=0.04");
  CHECK(eq.column == "delta");
  CHECK(fit::satisfies(eq, 0.04));
  CHECK(fit::satisfies(eq, 0.04000000000000001));
  CHECK(fit::satisfies(fit::parse_condition("delta == 4e-2"), 0.040));
  CHECK_FALSE(fit::satisfies(eq, 0.041));
  CHECK(fit::satisfies(fit::parse_condition("delta!=0.04"), 0.05));
  CHECK_FALSE(fit::satisfies(fit::parse_condition("delta<0.04"), 0.04));
  CHECK(fit::satisfies(fit::parse_condition("delta<=0.04"), 0.04000000000000001));
  CHECK(fit::satisfies(fit::parse_condition("porosity>0.1"), 0.2));
  CHECK_FALSE(fit::satisfies(fit::parse_condition("porosity>=0.3"), 0.2));
  CHECK_THROWS_AS(fit::parse_condition("delta"), UsageError);
  CHECK_THROWS_AS(fit::parse_condition("=0.04"), UsageError);
  CHECK_THROWS_WITH(fit::parse_condition("delta=abc"), Catch::Contains("'abc' is not a number"));
  CHECK_THROWS_AS(fit::parse_condition("delta!0.04"), UsageError);
}

TEST_CASE("rows are selected by every condition and grouped in increasing order of their key", "[fit]") {
  const auto t = table("p.csv", {"particles", "delta", "y"},
                       {{"50", "0.05", "1"}, {"32", "0.04", "2"}, {"50", "0.040", "3"}, {"32", "0.05", "4"},
                        {"50", "0.04000000000000001", "5"}});
  const auto rows = fit::merge_tables({t});
  const auto all = fit::select_rows(rows, {});
  CHECK(all.size() == 5);
  const auto d04 = fit::select_rows(rows, {fit::parse_condition("delta=0.04")});
  CHECK(d04 == std::vector<std::size_t>{1, 2, 4});
  const auto both = fit::select_rows(rows, {fit::parse_condition("delta=0.04"), fit::parse_condition("particles>40")});
  CHECK(both == std::vector<std::size_t>{2, 4});
  CHECK_THROWS_WITH(fit::select_rows(rows, {fit::parse_condition("phi=1")}), Catch::Contains("no column 'phi'"));

  const auto by_delta = fit::group_rows(rows, all, {1});
  REQUIRE(by_delta.size() == 2);
  CHECK(by_delta[0].key == std::vector<double>{0.04});
  CHECK(by_delta[0].rows == std::vector<std::size_t>{1, 2, 4});
  CHECK(by_delta[1].rows == std::vector<std::size_t>{0, 3});
  const auto by_two = fit::group_rows(rows, all, {0, 1});
  REQUIRE(by_two.size() == 4);
  CHECK(by_two[0].key == std::vector<double>{32, 0.04});
  CHECK(by_two[3].key == std::vector<double>{50, 0.05});
  CHECK(fit::group_rows(rows, all, {}).size() == 1);
  CHECK(fit::distinct_values(rows, all, 1) == std::vector<double>{0.04, 0.05});
}
