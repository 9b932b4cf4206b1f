#pragma once
// The analytic reference curve of each shell benchmark of Appendix B.5-B.7, tabulated on a grid
// at the thesis's parameters, as a CSV table (docs/formats.md) that
// scripts/figures/plot_shell_benchmark.gp overlays on a computed table with the same x and y columns.
//
// Cases and their columns (x first; the computed table must have the x column and the y
// column(s) marked *):
//   sphere          dP_E (dP/E), eps_r* (corrected SVK sphere), eps_r_printed (B.82),
//                   eps_r_linear; thesis Fig. B.4A (E = 25e6 Pa, nu = 1/3, t = 0.1 m, R0 = 2.5 m)
//   poisson         nu_input, nu_measured* (= nu_input for a continuum sheet), nu_springs (1/3,
//                   the spring-mesh value); Fig. B.4B
//   plate-point     r_R0 (r/R0), w_t* (w/t, along the load), w (m); Fig. B.5 (P0 = 5e3 N,
//                   R0 = 2.25 m, t = 0.1 m, E = 25e6 Pa, nu = 1/3; far outside the linear regime)
//   plate-uniform   r_R0, w_t*, w; Fig. B.6 (total load 1e3 N spread as q = 1e3/(pi R0^2) Pa)
//   plate-large     P_star ((q/E)(R0/t)^4), w_max_t* (B.88/B.89), w_max_t_linear (B.87),
//                   w_max_t_membrane (B.88's stretching term alone), w_max_t_von_karman (the
//                   von Karman plate equations solved numerically); Fig. B.7
//                   (nu = 0, R0 = 2.14 m, t = 0.1 m)
//   plates-contact  X (1 - eta_bar/R_i), F_hat* (F/(E t R0)), P_P0* (P/P_i), contact_radius_R0,
//                   contact_angle (Gamma, rad), volume_ratio (V/V_i); constant volume, Fig. B.9
//                   (P_i/E = 0.0025, t/R0 = 0.04, nu = 0.5)
//   buckling        gamma (Foppl-von Karman number), p_pc* (buckling pressure/p_c, 1 for the
//                   perfect continuum shell), R0_t, pc_R0_Y (p_c R0/Y); B.7 (nu = 1/3)
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace cmp::elasticity {

struct BenchmarkCurve {
  std::string name;                                       // the case
  std::vector<std::pair<std::string, std::string>> meta;  // "# key=value" lines: parameters, units
  std::vector<std::string> columns;                       // column names, x first
  std::vector<std::string> plotted;                       // the y columns a computed table is compared on
  std::vector<std::vector<double>> rows;
};

// The case names above, in that order.
const std::vector<std::string>& benchmark_case_names();

// The analytic curve of a case at the thesis's parameters, on `points` grid points (>= 2; the
// plates-contact case solves the membrane at each, about 1 ms a point). Throws cmp::UsageError
// for an unknown case (listing the names) or points < 2, cmp::ComputationError when the
// membrane solver fails.
BenchmarkCurve analytic_curve(const std::string& name, int points = 101);

// Writes the curve as CSV: its meta lines ("# case=...", "# source=analytic", "# compare=" the
// plotted columns, the parameters, "# references=" other analytic columns to draw beside the
// first plotted one where there are any, "# units=..."), the header, and the rows in shortest
// round-trip form.
void write_csv(std::ostream& out, const BenchmarkCurve& curve);

}  // namespace cmp::elasticity
