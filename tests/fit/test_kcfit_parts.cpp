// The parts of kcfit that live in lib/fit beside the fit itself: the --fix option
// (fix_option.hpp), one group's points and errors and its fit (group_fit.hpp), and the text
// of the stderr summary (fit_report.hpp).
#include "core/errors.hpp"
#include "fit/fit_report.hpp"
#include "fit/fit_inputs.hpp"
#include "fit/fix_option.hpp"
#include "fit/group_fit.hpp"
#include "fit/selection.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp;

namespace {

fit::Rows rows_of(std::vector<std::vector<std::string>> cells) {
  io::CsvTable t;
  t.file = "p.csv";
  t.header = {"porosity", "probability", "probability_error", "delta"};
  t.header_line = 1;
  for (std::size_t i = 0; i < cells.size(); ++i) t.row_lines.push_back(static_cast<long>(2 + i));
  t.rows = std::move(cells);
  return fit::merge_tables({t});
}

std::vector<std::size_t> all(const fit::Rows& rows) {
  std::vector<std::size_t> v;
  for (std::size_t i = 0; i < rows.cells.size(); ++i) v.push_back(i);
  return v;
}

}  // namespace

TEST_CASE("the fix option takes name=value items and returns a message for each bad one", "[fit]") {
  std::vector<std::string> problems;
  const auto fixed = fit::parse_fix({"phi_c=0.141,e=-0.38", "=3,b=x,q", "C=1e2"}, problems);
  REQUIRE(fixed.size() == 3);
  CHECK(fixed[0] == std::pair<std::string, double>("phi_c", 0.141));
  CHECK(fixed[1] == std::pair<std::string, double>("e", -0.38));
  CHECK(fixed[2] == std::pair<std::string, double>("C", 100));
  REQUIRE(problems.size() == 3);
  CHECK(problems[0] == "expected name=value[,name=value], e.g. --fix phi_c=0.141; got '=3'");
  CHECK(problems[1] == "'x' is not a finite number (in b=x)");
  CHECK(problems[2] == "expected name=value[,name=value], e.g. --fix phi_c=0.141; got 'q'");
}

TEST_CASE("zero errors take the smallest positive error of their group", "[fit]") {
  const auto rows = rows_of({{"0.10", "0", "0", "0.04"}, {"0.12", "0.3", "0.05", "0.04"},
                             {"0.14", "0.6", "0.02", "0.04"}, {"0.16", "1", "0", "0.04"}});
  const auto d = fit::group_data(rows, all(rows), 0, 1, 2, fit::Loss::Linear);
  CHECK(d.sigma == std::vector<double>{0.02, 0.05, 0.02, 0.02});
  CHECK(d.sigma_zero == 2);
  CHECK(d.sigma_column == "probability_error");
  CHECK(d.x == std::vector<double>{0.10, 0.12, 0.14, 0.16});
  // Without an error column the fit is unweighted.
  CHECK(fit::group_data(rows, all(rows), 0, 1, -1, fit::Loss::Linear).sigma.empty());
}

TEST_CASE("a negative error or a fraction under the ml loss is an input error at its line", "[fit]") {
  const auto rows = rows_of({{"0.10", "0", "0.1", "0.04"}, {"0.12", "0.2", "-0.1", "0.04"}});
  CHECK_THROWS_WITH(fit::group_data(rows, all(rows), 0, 1, 2, fit::Loss::Linear),
                    Catch::Contains("p.csv:3") && Catch::Contains("probability_error (the standard error of "
                                                                  "probability) is negative: -0.1"));
  CHECK_THROWS_WITH(fit::group_data(rows, all(rows), 0, 1, -1, fit::Loss::MaxLikelihood),
                    Catch::Contains("p.csv:3") && Catch::Contains("--loss ml needs probability to be 0 or 1, got 0.2"));
}

TEST_CASE("data no fit can describe is an input error naming the file and the group", "[fit]") {
  const auto rows = rows_of({{"0.10", "0.5", "0.1", "0.04"}, {"0.12", "0.5", "0.1", "0.04"},
                             {"0.14", "0.5", "0.1", "0.04"}, {"0.16", "0.5", "0.1", "0.04"}});
  const auto d = fit::group_data(rows, all(rows), 0, 1, 2, fit::Loss::Linear);
  CHECK(d.files == "p.csv");
  const auto& m = fit::find_model("sigmoid");
  CHECK_THROWS_MATCHES(fit::fit_group(m, d, {}, 0, 1, {"delta"}, {0.04}), InputError,
                       Catch::Message("p.csv: delta=0.04: no spread in y: all 4 points have y = 0.5 (x: porosity, y: "
                                      "probability)"));
}

TEST_CASE("a 0/1 outcome column holds only 0 and 1, a probability lies in [0, 1]", "[fit]") {
  io::CsvTable t;
  t.file = "o.csv";
  t.header = {"porosity", "percolates"};
  t.header_line = 1;
  t.rows = {{"0.1", "0"}, {"0.2", "1"}, {"0.3", "2"}};
  t.row_lines = {2, 3, 4};
  const auto rows = fit::merge_tables({t});
  const auto& m = fit::find_model("sigmoid");
  CHECK_THROWS_MATCHES(fit::check_outcomes(m, rows, all(rows), 1), InputError,
                       Catch::Message("o.csv:4: percolates holds 0/1 outcomes (model sigmoid), got 2"));
  CHECK_NOTHROW(fit::check_outcomes(fit::find_model("power"), rows, all(rows), 1));
  const auto p = rows_of({{"0.1", "0.2", "0", "0.04"}, {"0.2", "-0.1", "0", "0.04"}});
  CHECK_THROWS_MATCHES(fit::check_outcomes(m, p, all(p), 1), InputError,
                       Catch::Message("p.csv:3: probability must lie in [0, 1] for model sigmoid (a probability), got -0.1"));
}

TEST_CASE("a group whose errors are all zero is refused and named", "[fit]") {
  const auto rows = rows_of({{"0.10", "0", "0", "0.04"}, {"0.12", "0.2", "0", "0.04"},
                             {"0.14", "0.5", "0", "0.04"}, {"0.16", "1", "0", "0.04"}});
  const auto d = fit::group_data(rows, all(rows), 0, 1, 2, fit::Loss::Linear);
  const auto& m = fit::find_model("sigmoid");
  CHECK_THROWS_MATCHES(fit::fit_group(m, d, {}, 0, 1, {"delta"}, {0.04}), ComputationError,
                       Catch::Message("delta=0.04: every probability_error is 0: no weights (--sigma none fits unweighted)"));
  CHECK_THROWS_MATCHES(fit::fit_group(m, d, {}, 0, 1, {}, {}), ComputationError,
                       Catch::Message("every probability_error is 0: no weights (--sigma none fits unweighted)"));
  CHECK(fit::group_label({"delta", "particles"}, {"0.04", "50"}) == "delta=0.04,particles=50");
}

TEST_CASE("the summary gives each value to the second significant digit of its error", "[fit]") {
  fit::FitResult r;
  r.names = {"phi_c", "width", "e"};
  r.value = {0.141723, 0.00803, -0.38};
  r.error = {0.00224, 0.0, 0};
  r.fixed = {false, false, true};
  CHECK(fit::parameter_summary(r, false) == "phi_c = 0.1417 ± 0.0022, width = 0.00803 ± 0, e = -0.38 (fixed)");
  r.loss = fit::Loss::Log;
  r.r2 = 0.99431, r.chi2_dof = 0.02461;
  CHECK(fit::goodness_summary(r, false) == "R^2 (ln y) = 0.9943, chi^2/dof = 0.0246");
  CHECK(fit::goodness_summary(r, true) == "R^2 (ln y) = 0.9943, {/Symbol c}^2/dof = 0.0246");
}
