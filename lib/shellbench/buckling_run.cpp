#include "shellbench/buckling_run.hpp"

#include "shell/relax.hpp"
#include "shell/shell_model.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "elasticity/buckling.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cmp::shellbench {

using namespace cmp::shell;

void BucklingCase::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("buckling: ") + what);
  };
  require(gamma > 0 && std::isfinite(gamma), "the Foppl-von Karman number must be positive");
  require(step > 0 && std::isfinite(step), "the pressure step must be positive");
  require(resolution > 0 && resolution <= step, "the resolution must be positive and at most the step");
  require(max_pressure > step && std::isfinite(max_pressure), "the largest pressure must exceed one step");
  require(volume_drop > 0 && volume_drop < 1, "the volume drop must be in (0, 1)");
  require(kick >= 0 && std::isfinite(kick), "the kick must not be negative");
  require(relative_tolerance > 0, "the force tolerance must be positive");
  require(max_iterations > 0, "the iteration cap must be positive");
}

namespace {

// The rms of |x_i| - <|x_i|> over the vertices of x (centred on their mean).
double radial_roughness(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size() / 3;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) centre += x.segment<3>(3 * i);
  centre /= static_cast<double>(n);
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) r[i] = (x.segment<3>(3 * i) - centre).norm();
  return std::sqrt((r.array() - r.mean()).square().mean());
}

}  // namespace

BucklingResult buckling_run(const mesh::TriMesh& rest, const BucklingCase& c,
                            const std::function<void(const std::string&)>& note) {
  c.validate();
  constexpr double kNu = 1.0 / 3.0;  // the springs' Poisson ratio
  BucklingResult res;
  res.thickness = 1.0 / elasticity::radius_over_thickness(c.gamma, kNu);
  ShellModel m;
  m.stretching = c.stretching;
  m.bending = c.bending;
  m.pressure = "turgor";
  m.material = {1.0, kNu, res.thickness};
  ShellSystem s = make_shell_system(rest, m);
  res.critical_pressure =
      elasticity::buckling_pressure(m.material.stretching_modulus(), m.material.bending_rigidity(), 1.0);

  RelaxParameters rp;
  rp.relative_tolerance = c.relative_tolerance;
  rp.force_scale = default_force_scale(rest, 1.0, res.thickness);
  rp.fire.max_iterations = c.max_iterations;
  TurgorPressure& pressure = *s.pressure();
  const double v0 = pressure.volumes(span_of(s.x)).front();

  Random rng(c.seed);
  Eigen::VectorXd stable = s.x;  // the last stable state
  double stable_volume = v0;

  // Relaxes at p/p_c from the last stable state; true when the shell buckled.
  auto buckles = [&](double p) {
    s.x = stable;
    const double amplitude = c.kick * res.thickness;
    for (Eigen::Index i = 0; i < s.x.size(); ++i) s.x[i] += amplitude * rng.uniform(-1.0, 1.0);
    pressure.set_turgor(-p * res.critical_pressure);
    const double floor = (1.0 - c.volume_drop) * stable_volume;
    auto collapsed = [&] { return pressure.volumes(span_of(s.x)).front() < floor; };
    RelaxResult r;
    bool blown = false;
    try {
      r = relax(s, rp, [&](long, double) { return !collapsed(); });
    } catch (const ComputationError&) {
      // Elements crushed flat between two volume checks: only a collapsing shell gets there.
      blown = true;
      ++res.nonfinite;
    }
    ++res.relaxations;
    res.iterations += r.iterations;
    const bool down = blown || collapsed();
    if (!down && r.stop == RelaxStop::MaxIterations) ++res.unconverged;
    if (note)
      note(fmt::format("gamma {:g}: p/p_c = {:.4f}: {} ({} iterations, V/V0 = {:.4f})", c.gamma, p,
                       blown ? "buckled (non-finite force)" : down ? "buckled" : relax_stop_name(r.stop), r.iterations,
                       pressure.volumes(span_of(s.x)).front() / v0));
    if (!down) {
      stable = s.x;
      stable_volume = pressure.volumes(span_of(s.x)).front();
    }
    return down;
  };

  double lo = 0, hi = 0;
  for (double p = c.step; p <= c.max_pressure + 1e-12; p += c.step) {
    if (buckles(p)) {
      hi = p;
      res.buckled = true;
      break;
    }
    lo = p;
  }
  if (res.buckled) {
    while (hi - lo > c.resolution * (1 + 1e-9)) {
      const double mid = 0.5 * (lo + hi);
      (buckles(mid) ? hi : lo) = mid;
    }
  }
  res.pressure = hi;
  res.stable_pressure = lo;
  res.stable_volume = stable_volume / v0;
  res.stable_roughness = radial_roughness(stable) / res.thickness;
  return res;
}

}  // namespace cmp::shellbench
