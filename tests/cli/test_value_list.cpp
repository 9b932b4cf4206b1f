#include "cli/value_list.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

using cmp::cli::parse_value_list;

TEST_CASE("value lists: an inclusive range or a comma list, every bad shape refused") {
  CHECK(parse_value_list("0.6:0.8:0.1") == std::vector<double>{0.6, 0.6 + 0.1, 0.6 + 2 * 0.1});
  CHECK(parse_value_list("0:0.3:0.1").size() == 4);  // LAST on the grid within round-off
  CHECK(parse_value_list("0.7,0.6") == std::vector<double>{0.7, 0.6});
  CHECK(parse_value_list("5") == std::vector<double>{5});
  CHECK_THROWS_WITH(parse_value_list("0.6:0.8:0"), Catch::Contains("the step of '0.6:0.8:0' must be positive"));
  CHECK_THROWS_WITH(parse_value_list("0.8:0.6:0.1"), Catch::Contains("LAST is below FIRST"));
  CHECK_THROWS_WITH(parse_value_list("0:1:1e-6"), Catch::Contains("more than 100000 values"));
  CHECK_THROWS_WITH(parse_value_list("0.6:0.8"), Catch::Contains("expected FIRST:LAST:STEP or a comma list"));
  CHECK_THROWS_WITH(parse_value_list("0.6,x"), Catch::Contains("'x' in '0.6,x' is not a number"));
  CHECK_THROWS_WITH(parse_value_list("0.6,"), Catch::Contains("'' in '0.6,' is not a number"));
  CHECK_THROWS_WITH(parse_value_list("nan"), Catch::Contains("is not a number"));
  CHECK_THROWS_AS(parse_value_list(""), cmp::UsageError);
}
