#include "elasticity/benchmark_curves.hpp"

#include "core/errors.hpp"
#include "core/registry.hpp"
#include "elasticity/buckling.hpp"
#include "elasticity/clamped_plate.hpp"
#include "elasticity/membrane_contact.hpp"
#include "elasticity/pressurised_sphere.hpp"
#include "elasticity/von_karman_plate.hpp"
#include "io/csv.hpp"

#include <cmath>
#include <functional>
#include <map>

namespace cmp::elasticity {

namespace {
using io::format_number;

std::vector<double> linear_grid(double lo, double hi, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = lo + (hi - lo) * i / (n - 1);
  return x;
}
std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1));
  return x;
}
void sheet_meta(BenchmarkCurve& c, const Sheet& s) {
  c.meta.push_back({"E_Pa", format_number(s.youngs_modulus)});
  c.meta.push_back({"nu", format_number(s.poisson_ratio)});
  c.meta.push_back({"t_m", format_number(s.thickness)});
}

BenchmarkCurve sphere(int n) {
  const Sheet s{25e6, 1.0 / 3.0, 0.1};
  const double R0 = 2.5;
  BenchmarkCurve c{"sphere", {}, {"dP_E", "eps_r", "eps_r_printed", "eps_r_linear"}, {"eps_r"}, {}};
  sheet_meta(c, s);
  c.meta.push_back({"R0_m", format_number(R0)});
  c.meta.push_back({"references", "eps_r_printed eps_r_linear"});
  c.meta.push_back({"units", "dP_E pressure difference / E; eps_r = lambda - 1 = cbrt(V/V0) - 1 of the SVK sphere "
                             "(corrected B.81); eps_r_printed from the printed B.82; eps_r_linear its small-strain limit"});
  for (double p : linear_grid(0.0, 1e-2, n)) {
    const double dP = p * s.youngs_modulus;
    c.rows.push_back({p, sphere_stretch(s, R0, dP) - 1, sphere_strain_printed(s, R0, dP), sphere_strain_linear(s, R0, dP)});
  }
  return c;
}

BenchmarkCurve poisson(int n) {
  BenchmarkCurve c{"poisson", {}, {"nu_input", "nu_measured", "nu_springs"}, {"nu_measured"}, {}};
  c.meta.push_back({"references", "nu_springs"});
  c.meta.push_back({"units", "nu_input the material's Poisson ratio; nu_measured = -eps_transverse/eps_axial of a "
                             "uniaxially stretched continuum sheet; nu_springs the spring-mesh value"});
  for (double nu : linear_grid(0.1, 0.45, n)) c.rows.push_back({nu, nu, 1.0 / 3.0});
  return c;
}

BenchmarkCurve plate(bool point, int n) {
  const Sheet s{25e6, 1.0 / 3.0, 0.1};
  const double R0 = 2.25, P0 = point ? 5e3 : 1e3, q = P0 / (M_PI * R0 * R0);
  BenchmarkCurve c{point ? "plate-point" : "plate-uniform", {}, {"r_R0", "w_t", "w_m"}, {"w_t"}, {}};
  sheet_meta(c, s);
  c.meta.push_back({"R0_m", format_number(R0)});
  c.meta.push_back({point ? "load_N" : "total_load_N", format_number(P0)});
  if (!point) c.meta.push_back({"pressure_Pa", format_number(q)});
  const double wmax = point ? point_load_max_deflection(s, R0, P0) : uniform_load_max_deflection(s, R0, q);
  c.meta.push_back({"w_max_m", format_number(wmax)});
  c.meta.push_back({"linear_regime", wmax < 0.5 * s.thickness ? "yes (w_max < t/2)" : "no (w_max >= t/2: linear theory overestimates)"});
  c.meta.push_back({"units", "r_R0 distance from the centre / R0; w_t deflection along the load / t (linear plate "
                             "theory, B.84 or B.86); w_m the deflection in m"});
  for (double x : linear_grid(0.0, 1.0, n)) {
    const double r = std::min(R0, x * R0);
    const double w = point ? point_load_deflection(s, R0, P0, r) : uniform_load_deflection(s, R0, q, r);
    c.rows.push_back({x, w / s.thickness, w});
  }
  return c;
}

BenchmarkCurve plate_large(int n) {
  const Sheet s{25e6, 0.0, 0.1};
  const double R0 = 2.14;
  BenchmarkCurve c{"plate-large", {}, {"P_star", "w_max_t", "w_max_t_linear", "w_max_t_membrane", "w_max_t_von_karman"},
                   {"w_max_t"},
                   {}};
  sheet_meta(c, s);
  c.meta.push_back({"R0_m", format_number(R0)});
  c.meta.push_back({"references", "w_max_t_linear w_max_t_membrane w_max_t_von_karman"});
  c.meta.push_back({"units", "P_star = (q/E)(R0/t)^4 for a uniform pressure q; w_max_t central deflection / t from "
                             "B.88 (B.89 with its (1 - nu^2) in the numerator); w_max_t_linear from B.87 (bending alone); "
                             "w_max_t_membrane from B.88's cubic term alone (stretching alone, the membrane-only model); "
                             "w_max_t_von_karman the numerical solution of the von Karman plate equations (immovable edge)"});
  const std::vector<double> stars = log_grid(0.1, 1e4, n);
  const std::vector<double> exact = von_karman_max_deflection(s.poisson_ratio, stars);
  for (std::size_t i = 0; i < stars.size(); ++i) {
    const double ps = stars[i], q = plate_pressure_from_star(s, R0, ps);
    const double nu = s.poisson_ratio;
    c.rows.push_back({ps, large_deflection_max_deflection(nu, ps), uniform_load_max_deflection(s, R0, q) / s.thickness,
                      std::cbrt(12 * (1 - nu * nu) / 64 * ps / (0.5 * (1 + nu))), exact[i]});
  }
  return c;
}

BenchmarkCurve plates_contact(int n) {
  const Sheet s{1.0, 0.5, 0.04};
  const double R0 = 1.0, P_i = 0.0025;
  const InflatedMembrane m(s, R0, P_i);
  BenchmarkCurve c{"plates-contact",
                   {},
                   {"X", "F_hat", "P_P0", "contact_radius_R0", "contact_angle", "volume_ratio"},
                   {"F_hat", "P_P0"},
                   {}};
  c.meta.push_back({"P0_E", format_number(P_i / s.youngs_modulus)});
  c.meta.push_back({"t_R0", format_number(s.thickness / R0)});
  c.meta.push_back({"nu", format_number(s.poisson_ratio)});
  c.meta.push_back({"fill", "constant volume"});
  c.meta.push_back({"inflated_stretch", format_number(m.inflated_stretch())});
  c.meta.push_back({"units", "X = 1 - eta_bar/R_i (eta_bar plate to equator, R_i inflated radius); F_hat = F/(E t R0), "
                             "F the force on one plate; P_P0 = P/P_0, P_0 the inflation pressure; contact_radius_R0 = r_c/R0; "
                             "contact_angle Gamma in rad (rest polar angle of the contact edge); volume_ratio V/V_i"});
  c.rows.push_back({0.0, 0.0, 1.0, 0.0, 0.0, 1.0});
  std::vector<double> X = linear_grid(0.0, 0.6, n);
  X.erase(X.begin());
  for (const auto& st : m.sweep(X, Fill::ConstantVolume))
    c.rows.push_back({st.compression, st.force / m.force_scale(), st.pressure / P_i, st.contact_radius / R0,
                      st.contact_angle, st.volume / m.inflated_volume()});
  return c;
}

BenchmarkCurve buckling(int n) {
  const double nu = 1.0 / 3.0;
  BenchmarkCurve c{"buckling", {}, {"gamma", "p_pc", "R0_t", "pc_R0_Y"}, {"p_pc"}, {}};
  c.meta.push_back({"nu", format_number(nu)});
  c.meta.push_back({"units", "gamma = Y R0^2/kappa; p_pc buckling pressure / p_c with p_c = 4 sqrt(kappa Y)/R0^2 "
                             "(1: the perfect shell); R0_t = R0/t of a continuum sheet; pc_R0_Y = p_c R0/Y"});
  for (double g : log_grid(1e3, 5e4, n)) c.rows.push_back({g, 1.0, radius_over_thickness(g, nu), 4.0 / std::sqrt(g)});
  return c;
}
// The cases, in the order of Appendix B (shellpack bench-mechanics runs the same names).
struct CurveCase {
  const char* name;
  BenchmarkCurve (*curve)(int points);
};
const CurveCase kCurves[] = {
    {"sphere", &sphere},
    {"poisson", &poisson},
    {"plate-point", [](int n) { return plate(true, n); }},
    {"plate-uniform", [](int n) { return plate(false, n); }},
    {"plate-large", &plate_large},
    {"plates-contact", &plates_contact},
    {"buckling", &buckling},
};
}  // namespace

const std::vector<std::string>& benchmark_case_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& c : kCurves) v.push_back(c.name);
    return v;
  }();
  return names;
}

BenchmarkCurve analytic_curve(const std::string& name, int points) {
  const CurveCase& c = find_style(kCurves, name, "benchmark case");
  if (points < 2) throw UsageError("analytic curve: needs at least 2 points");
  return c.curve(points);
}

void write_csv(std::ostream& out, const BenchmarkCurve& c) {
  io::CsvWriter w(out);
  w.meta("case", c.name);
  w.meta("source", "analytic");
  std::string plotted;
  for (const auto& p : c.plotted) plotted += (plotted.empty() ? "" : " ") + p;
  w.meta("compare", plotted);
  for (const auto& [k, v] : c.meta) w.meta(k, v);
  w.header(c.columns);
  for (const auto& row : c.rows) {
    std::vector<std::string> cells;
    for (double x : row) cells.push_back(format_number(x));
    w.row(cells);
  }
}

}  // namespace cmp::elasticity
