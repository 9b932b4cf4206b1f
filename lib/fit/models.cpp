#include "fit/models.hpp"

#include "core/errors.hpp"
#include "core/registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmp::fit {

int Model::index(const std::string& parameter) const {
  for (std::size_t k = 0; k < params.size(); ++k)
    if (params[k].name == parameter) return static_cast<int>(k);
  return -1;
}

namespace {

double min_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

// Trial thresholds below the smallest x: a little, some and far below, so that both a
// threshold close to the data and one far from it are tried.
std::vector<double> threshold_starts(const std::vector<double>& x) {
  const double lo = min_of(x), range = max_of(x) - lo;
  const double scale = range > 0 ? range : std::abs(lo) + 1.0;
  return {lo - 0.02 * scale, lo - 0.1 * scale, lo - 0.3 * scale, lo - 1.0 * scale};
}

// Grid threshold x exponent; C (index 0) is filled in from the data by the driver.
std::vector<std::vector<double>> grid(const std::vector<double>& thresholds, const std::vector<double>& exponents) {
  std::vector<std::vector<double>> s;
  for (double e : exponents)
    for (double t : thresholds) s.push_back({1.0, t, e});
  return s;
}

bool in_unit_interval(double x) { return x > 0 && x < 1; }

// KC-type factor x^2 / (1 - x)^2 of Eq. 5.8 (R_h ~ phi / (1 - phi), squared).
double rh2(double x) { return x * x / ((1 - x) * (1 - x)); }

// C (x - phi_c)^a * h(x) and its gradient in (C, phi_c, a) where a = shift + p[2] (or the
// fixed exponent when has_exponent is false).
double shifted_power(double x, const double* p, double exponent, double h) {
  return p[0] * std::pow(x - p[1], exponent) * h;
}
void shifted_power_gradient(double x, const double* p, double exponent, double h, double* g, bool has_exponent) {
  const double d = x - p[1];
  const double base = std::pow(d, exponent) * h;
  g[0] = base;
  g[1] = -p[0] * exponent * std::pow(d, exponent - 1) * h;
  if (has_exponent) g[2] = p[0] * base * std::log(d);
}

// ln of C (x - phi_c)^a h(x) with ln h given, and its gradient in (C, phi_c[, a]).
double log_shifted_power(double x, const double* p, double exponent, double log_h) {
  const double d = x - p[1];
  if (!(p[0] > 0) || !(d > 0)) return std::numeric_limits<double>::quiet_NaN();
  return std::log(p[0]) + exponent * std::log(d) + log_h;
}
void log_shifted_power_gradient(double x, const double* p, double exponent, double* g, bool has_exponent) {
  const double d = x - p[1];
  g[0] = 1 / p[0];
  g[1] = -exponent / d;
  if (has_exponent) g[2] = std::log(d);
}
double log_rh2(double x) { return 2 * std::log(x / (1 - x)); }

std::vector<Model> make_models() {
  std::vector<Model> m;
  const Parameter C{"C", "prefactor", 1.0, 0.0, kInf};
  const Parameter phi_c{"phi_c", "percolation threshold (kept below the smallest x)", 0.1};

  {
    Model k;
    k.name = "kc-classical";
    k.x_columns = {"porosity"};
    k.y_columns = {"permeability_delta2", "permeability_d02", "permeability"};
    k.title = "{/Symbol k} = C {/Symbol f}^3 / (1 - {/Symbol f})^2";
    k.formula = "C x^3 / (1 - x)^2";
    k.source = "classical Kozeny-Carman (thesis 5.3.4, Fig. S5.5 A-B)";
    k.params = {C};
    k.value = [](double x, const double* p) { return p[0] * x * rh2(x); };
    k.gradient = [](double x, const double* p, double* g) { g[0] = x * rh2(x); };
    k.x_in_domain = in_unit_interval;
    k.domain = "0 < x < 1";
    k.scale = 0;
    k.starts = [](const auto&, const auto&) { return std::vector<std::vector<double>>{{1.0}}; };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "kc-percolation";
    k.x_columns = {"porosity"};
    k.y_columns = {"permeability_delta2", "permeability_d02", "permeability"};
    k.title = "{/Symbol k} = C ({/Symbol f} - {/Symbol f}_c)^{{/Symbol g} + 0.76} {/Symbol f}^2 / (1 - {/Symbol f})^2";
    k.formula = "C (x - phi_c)^(gamma + 0.76) x^2 / (1 - x)^2";
    k.source = "thesis Eq. 5.8, Table S5.1 model i)";
    k.params = {C, phi_c, {"gamma", "exponent of the reduced porosity (0.76 comes from tau_H^-2)", 1.0}};
    k.value = [](double x, const double* p) { return shifted_power(x, p, p[2] + 0.76, rh2(x)); };
    k.gradient = [](double x, const double* p, double* g) {
      shifted_power_gradient(x, p, p[2] + 0.76, rh2(x), g, true);
    };
    k.log_value = [](double x, const double* p) { return log_shifted_power(x, p, p[2] + 0.76, log_rh2(x)); };
    k.log_gradient = [](double x, const double* p, double* g) {
      log_shifted_power_gradient(x, p, p[2] + 0.76, g, true);
    };
    k.x_in_domain = in_unit_interval;
    k.domain = "0 < x < 1, x > phi_c";
    k.threshold = 1;
    k.scale = 0;
    k.starts = [](const auto& x, const auto&) { return grid(threshold_starts(x), {0.5, 1.0, 2.0}); };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "kc-fixed";
    k.x_columns = {"porosity"};
    k.y_columns = {"permeability_delta2", "permeability_d02", "permeability"};
    k.title = "{/Symbol k} = C ({/Symbol f} - {/Symbol f}_c)^{2.52} {/Symbol f}^2 / (1 - {/Symbol f})^2";
    k.formula = "C (x - phi_c)^2.52 x^2 / (1 - x)^2";
    k.source = "thesis Eq. 2.52 / Table S5.1 model ii) (gamma = 1.76, n_c ~ dphi^1.76 of 5.5.5)";
    k.params = {C, phi_c};
    k.value = [](double x, const double* p) { return shifted_power(x, p, kFixedKcExponent, rh2(x)); };
    k.gradient = [](double x, const double* p, double* g) {
      shifted_power_gradient(x, p, kFixedKcExponent, rh2(x), g, false);
    };
    k.log_value = [](double x, const double* p) { return log_shifted_power(x, p, kFixedKcExponent, log_rh2(x)); };
    k.log_gradient = [](double x, const double* p, double* g) {
      log_shifted_power_gradient(x, p, kFixedKcExponent, g, false);
    };
    k.x_in_domain = in_unit_interval;
    k.domain = "0 < x < 1, x > phi_c";
    k.threshold = 1;
    k.scale = 0;
    k.starts = [](const auto& x, const auto&) {
      std::vector<std::vector<double>> s;
      for (double t : threshold_starts(x)) s.push_back({1.0, t});
      return s;
    };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "power";
    k.x_columns = {"porosity"};
    k.y_columns = {"permeability_delta2", "permeability_d02", "permeability"};
    k.title = "{/Symbol k} = C ({/Symbol f} - {/Symbol f}_c)^e";
    k.formula = "C (x - phi_c)^e";
    k.source = "power-law ansatz kappa ~ dphi^e (thesis 5.3.4, Table S5.1 model iii)";
    k.params = {C, phi_c, {"e", "exponent", 2.0}};
    k.value = [](double x, const double* p) { return shifted_power(x, p, p[2], 1.0); };
    k.gradient = [](double x, const double* p, double* g) { shifted_power_gradient(x, p, p[2], 1.0, g, true); };
    k.log_value = [](double x, const double* p) { return log_shifted_power(x, p, p[2], 0.0); };
    k.log_gradient = [](double x, const double* p, double* g) { log_shifted_power_gradient(x, p, p[2], g, true); };
    k.x_in_domain = [](double) { return true; };
    k.domain = "x > phi_c";
    k.threshold = 1;
    k.scale = 0;
    k.starts = [](const auto& x, const auto&) { return grid(threshold_starts(x), {1.0, 2.5, 4.0}); };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "hydraulic-radius";
    k.x_columns = {"porosity"};
    k.y_columns = {"rh_sites_d0", "hydraulic_radius"};
    k.title = "R_h = C {/Symbol f} / (1 - {/Symbol f})";
    k.formula = "C x / (1 - x)";
    k.source = "R_h ~ phi / (1 - phi) (thesis Fig. 5.3, Eq. 5.6)";
    k.params = {C};
    k.value = [](double x, const double* p) { return p[0] * x / (1 - x); };
    k.gradient = [](double x, const double*, double* g) { g[0] = x / (1 - x); };
    k.x_in_domain = [](double x) { return x >= 0 && x < 1; };
    k.domain = "0 <= x < 1";
    k.scale = 0;
    k.starts = [](const auto&, const auto&) { return std::vector<std::vector<double>>{{1.0}}; };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "tortuosity";
    k.x_columns = {"porosity"};
    k.y_columns = {"tortuosity"};
    k.title = "{/Symbol t}_H = C ({/Symbol f} - {/Symbol f}_c)^e";
    k.formula = "C (x - phi_c)^e, e = -0.38 unless freed (--free e)";
    k.source = "tau_H ~ dphi^-0.38 (thesis 5.5.4, Fig. 5.4 B, Table S5.1)";
    Parameter e{"e", "exponent nu (1 - D) = -0.38 of percolation theory", kTortuosityExponent};
    e.fixed_by_default = true;
    k.params = {C, phi_c, e};
    k.value = [](double x, const double* p) { return shifted_power(x, p, p[2], 1.0); };
    k.gradient = [](double x, const double* p, double* g) { shifted_power_gradient(x, p, p[2], 1.0, g, true); };
    k.log_value = [](double x, const double* p) { return log_shifted_power(x, p, p[2], 0.0); };
    k.log_gradient = [](double x, const double* p, double* g) { log_shifted_power_gradient(x, p, p[2], g, true); };
    k.x_in_domain = [](double) { return true; };
    k.domain = "x > phi_c";
    k.threshold = 1;
    k.scale = 0;
    k.starts = [](const auto& x, const auto&) { return grid(threshold_starts(x), {kTortuosityExponent, -1.0}); };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "threshold";
    k.x_columns = {"delta"};
    k.y_columns = {"phi_c"};
    k.title = "{/Symbol f}_c({/Symbol d}) = {/Symbol f}_c^* + A {/Symbol d}^{/Symbol b}";
    k.formula = "phi_c_star + A x^beta";
    k.source = "phi_c(delta) - phi_c* = A delta^beta (thesis 5.5.6, Fig. 5.2 D, Table S5.1)";
    k.params = {{"phi_c_star", "threshold in the continuum limit x -> 0", 0.05},
                {"A", "amplitude", 1.0},
                {"beta", "exponent", 1.0, 0.0, kInf}};
    k.value = [](double x, const double* p) { return p[0] + p[1] * std::pow(x, p[2]); };
    k.gradient = [](double x, const double* p, double* g) {
      const double xb = std::pow(x, p[2]);
      g[0] = 1.0;
      g[1] = xb;
      g[2] = p[1] * xb * std::log(x);
    };
    k.x_in_domain = [](double x) { return x > 0; };
    k.domain = "x > 0";
    k.starts = [](const std::vector<double>& x, const std::vector<double>& y) {
      // For each trial beta, phi_c_star and A by linear least squares on (1, x^beta).
      std::vector<std::vector<double>> s;
      for (double beta : {0.5, 1.0, 1.5, 2.0, 3.0}) {
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
          const double t = std::pow(x[i], beta);
          n += 1, sx += t, sy += y[i], sxx += t * t, sxy += t * y[i];
        }
        const double det = n * sxx - sx * sx;
        const double a = det != 0 ? (n * sxy - sx * sy) / det : 1.0;
        const double b = n > 0 ? (sy - a * sx) / n : 0.0;
        s.push_back({b, a, beta});
      }
      return s;
    };
    m.push_back(k);
  }
  {
    Model k;
    k.name = "sigmoid";
    k.x_columns = {"porosity"};
    k.y_columns = {"percolates", "probability"};
    k.title = "P({/Symbol f}) = 1 / (1 + exp(-({/Symbol f} - {/Symbol f}_c) / w))";
    k.formula = "1 / (1 + exp(-(x - phi_c) / width))";
    k.source = "percolation probability, phi_c where it is 1/2 (thesis 5.5.6, Fig. 5.2 C)";
    k.params = {{"phi_c", "x where the probability is 1/2", 0.1},
                {"width", "width of the transition (> 0)", 0.01, 0.0, kInf}};
    k.value = [](double x, const double* p) { return 1.0 / (1.0 + std::exp(-(x - p[0]) / p[1])); };
    k.gradient = [](double x, const double* p, double* g) {
      const double f = 1.0 / (1.0 + std::exp(-(x - p[0]) / p[1]));
      g[0] = -f * (1 - f) / p[1];
      g[1] = -f * (1 - f) * (x - p[0]) / (p[1] * p[1]);
    };
    k.x_in_domain = [](double) { return true; };
    k.domain = "all x";
    k.probability = true;
    k.outcome_columns = {"percolates"};
    k.starts = [](const std::vector<double>& x, const std::vector<double>& y) {
      // Centre: mean x of the points with an intermediate probability, else the midpoint
      // between the largest x with y < 1/2 and the smallest with y >= 1/2.
      double sum = 0, n = 0, below = -kInf, above = kInf;
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (y[i] > 0.2 && y[i] < 0.8) sum += x[i], n += 1;
        if (y[i] < 0.5) below = std::max(below, x[i]);
        else above = std::min(above, x[i]);
      }
      const double lo = min_of(x), hi = max_of(x);
      double centre = n > 0 ? sum / n : 0.5 * (lo + hi);
      if (n == 0 && std::isfinite(below) && std::isfinite(above)) centre = 0.5 * (below + above);
      const double range = hi > lo ? hi - lo : 1.0;
      return std::vector<std::vector<double>>{{centre, range / 20}, {centre, range / 5}, {centre, range / 100}};
    };
    m.push_back(k);
  }
  return m;
}

}  // namespace

const std::vector<Model>& models() {
  static const std::vector<Model> all = make_models();
  return all;
}

const Model& find_model(const std::string& name) { return find_style(models(), name, "model"); }

}  // namespace cmp::fit
