// The goodness-of-fit measures each loss reports (lib/fit/fit.hpp) and weighted least squares,
// checked against closed forms.
#include "core/errors.hpp"
#include "core/random.hpp"
#include "fit/fit.hpp"
#include "fit/fit_table.hpp"
#include "fit/plot.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using namespace cmp;


TEST_CASE("maximum likelihood reports deviance and McFadden pseudo R2 against the constant model", "[fit]") {
  const auto& m = fit::find_model("sigmoid");
  Random rng(3);
  std::vector<double> x, y;
  for (int i = 0; i < 400; ++i) {
    x.push_back(rng.uniform(0.08, 0.22));
    const double p[] = {0.141, 0.01};
    y.push_back(rng.uniform(0, 1) < m.value(x.back(), p) ? 1 : 0);
  }
  fit::FitOptions o;
  o.loss = fit::Loss::MaxLikelihood;
  const auto r = fit::fit(m, x, y, o);
  double ones = 0;
  for (double v : y) ones += v;
  const double p = ones / y.size();
  CHECK(r.null_log_likelihood == Approx(ones * std::log(p) + (y.size() - ones) * std::log(1 - p)));
  CHECK(r.deviance == Approx(-2 * r.log_likelihood));
  CHECK(r.pseudo_r2 == Approx(1 - r.log_likelihood / r.null_log_likelihood));
  CHECK(r.pseudo_r2 > 0.5);
  CHECK(r.pseudo_r2 < 1);
  const auto g = fit::goodness(r);
  REQUIRE(g.size() == 5);
  CHECK(g[0].first == "log_likelihood");
  CHECK(g[3].first == "pseudo_r2");
}

TEST_CASE("weighted least squares equals the closed form of a weighted straight line", "[fit]") {
  // threshold with beta fixed at 1 is a straight line phi_c_star + A x: weighted linear
  // regression in closed form.
  const auto& m = fit::find_model("threshold");
  const std::vector<double> x{0.02, 0.03, 0.04, 0.05, 0.06, 0.07};
  const std::vector<double> y{0.10, 0.118, 0.139, 0.151, 0.176, 0.188};
  const std::vector<double> s{0.001, 0.002, 0.004, 0.002, 0.01, 0.003};
  fit::FitOptions o;
  o.fixed = {{"beta", 1.0}};
  const auto r = fit::fit(m, x, y, o, s);
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = 1 / (s[i] * s[i]);
    sw += w, sx += w * x[i], sy += w * y[i], sxx += w * x[i] * x[i], sxy += w * x[i] * y[i];
  }
  const double det = sw * sxx - sx * sx, slope = (sw * sxy - sx * sy) / det, icpt = (sy - slope * sx) / sw;
  CHECK(r.value[0] == Approx(icpt).epsilon(1e-8));
  CHECK(r.value[1] == Approx(slope).epsilon(1e-8));
  double chi2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) chi2 += std::pow((icpt + slope * x[i] - y[i]) / s[i], 2);
  CHECK(r.weighted);
  CHECK(r.rss == Approx(chi2).epsilon(1e-8));
  CHECK(r.chi2_dof == Approx(chi2 / 4).epsilon(1e-8));
  // curve_fit's covariance: (J^T W J)^-1 chi2 / dof.
  CHECK(r.error[1] == Approx(std::sqrt(sw / det * chi2 / 4)).epsilon(1e-6));
  const auto unweighted = fit::fit(m, x, y, o);
  CHECK_FALSE(unweighted.weighted);
  CHECK(unweighted.value[1] != Approx(slope).epsilon(1e-4));
  CHECK(unweighted.chi2_dof == Approx(unweighted.rss / 4));
  fit::FitOptions log = o;
  log.loss = fit::Loss::Log;
  CHECK_THROWS_AS(fit::fit(m, x, y, log, s), UsageError);
}

TEST_CASE("figure formats come from the extension and 0 1 outcomes are binned with Wilson intervals", "[fit]") {
  CHECK(fit::plot_format("a/fit.png") == fit::PlotFormat::Png);
  CHECK(fit::plot_format("FIT.SVG") == fit::PlotFormat::Svg);
  CHECK(fit::plot_format("x.pdf") == fit::PlotFormat::Pdf);
  CHECK_FALSE(fit::plot_format("x.txt").has_value());
  CHECK_FALSE(fit::plot_format("png").has_value());
  CHECK_FALSE(fit::plot_format("a.png/fit").has_value());
  const std::vector<double> x{0.0, 0.1, 0.2, 0.3, 0.9, 1.0};
  const std::vector<double> y{0, 0, 0, 1, 1, 1};
  const auto b = fit::binned_outcomes(x, y, 2);
  REQUIRE(b.x.size() == 2);
  CHECK(b.x[0] == Approx(0.15));
  CHECK(b.y[0] == Approx(0.25));
  CHECK(b.y[1] == Approx(1.0));
  // Wilson, z = 1, n = 2, f = 1: centre (1 + 1/4) / 1.5, half sqrt(1/16) / 1.5.
  CHECK(b.low[1] == Approx((1.25 - 0.25) / 1.5));
  CHECK(b.high[1] == Approx(1.0));
  CHECK(b.low[0] < b.y[0]);
  CHECK(b.high[0] > b.y[0]);
  CHECK(fit::axis_label("porosity") == "porosity {/Symbol f}");
  CHECK(fit::axis_label("delta") == "voxel side {/Symbol d} / D_0");
  CHECK(fit::axis_label("my_col") == "my\\_col");
}
