#include "elasticity/benchmark_curves.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/input.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace cmp::elasticity;

TEST_CASE("every analytic benchmark curve is a CSV table that reads back", "[elasticity][curves]") {
  for (const auto& name : benchmark_case_names()) {
    INFO(name);
    const auto c = analytic_curve(name, 11);
    CHECK(c.name == name);
    REQUIRE(c.rows.size() == 11);
    for (const auto& row : c.rows) CHECK(row.size() == c.columns.size());
    for (const auto& p : c.plotted) CHECK(std::find(c.columns.begin(), c.columns.end(), p) != c.columns.end());
    std::ostringstream out;
    write_csv(out, c);
    const std::string path = std::string(CMP_BIN_DIR) + "/../curve_test_" + name + ".csv";
    std::ofstream(path) << out.str();
    const auto t = cmp::io::read_csv(path);
    std::remove(path.c_str());
    CHECK(t.header == c.columns);
    REQUIRE(t.rows.size() == c.rows.size());
    CHECK(*t.find_meta("case") == name);
    CHECK(t.find_meta("units") != nullptr);
    for (std::size_t i = 0; i < c.rows.size(); ++i)
      for (std::size_t j = 0; j < c.columns.size(); ++j) CHECK(t.number(i, static_cast<int>(j)) == c.rows[i][j]);
    // x increases along the table.
    for (std::size_t i = 1; i < c.rows.size(); ++i) CHECK(c.rows[i][0] > c.rows[i - 1][0]);
  }
  CHECK_THROWS_WITH(analytic_curve("spher"), Catch::Contains("unknown benchmark case 'spher' (known: sphere, poisson"));
  CHECK_THROWS_AS(analytic_curve("sphere", 1), cmp::UsageError);
}

TEST_CASE("analytic curves end at the reference numbers", "[elasticity][curves]") {
  CHECK(analytic_curve("sphere", 11).rows.back()[1] == Approx(0.08680).margin(5e-6));
  CHECK(analytic_curve("plate-large", 11).rows.back()[1] == Approx(15.49325).margin(5e-6));
  CHECK(analytic_curve("plate-point", 11).rows.front()[2] == Approx(0.21486).margin(5e-6));
  CHECK(analytic_curve("buckling", 2).rows.front()[3] == Approx(0.12649).margin(5e-6));
  const auto contact = analytic_curve("plates-contact", 7);
  CHECK(contact.rows.front()[1] == 0.0);
  for (std::size_t i = 1; i < contact.rows.size(); ++i) CHECK(contact.rows[i][1] > contact.rows[i - 1][1]);
  CHECK(contact.rows.back()[5] == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("the large-deflection curve lies below both of its one-term limits", "[elasticity][curves]") {
  for (const auto& row : analytic_curve("plate-large", 21).rows) {
    CHECK(row[1] <= row[2] * (1 + 1e-12));
    CHECK(row[1] <= row[3] * (1 + 1e-12));
  }
}
