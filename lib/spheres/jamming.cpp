#include "spheres/jamming.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/rattlers.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace cmp::spheres {

void JammingParameters::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(what);
  };
  require(initial_volume_fraction > 0 && initial_volume_fraction < 0.5, "initial volume fraction must lie in (0, 0.5)");
  require(initial_step > 0 && initial_step < 0.5, "initial radius step eps_r must lie in (0, 0.5)");
  require(min_pressure > 0 && std::isfinite(min_pressure), "P_min must be positive");
  require(max_tries > 0, "max tries must be positive");
  require(max_size_changes > 0, "max size changes must be positive");
  require(step_iteration_cap >= 0, "FIRE iteration cap per size change must not be negative");
  material.validate();
  fire.validate();
}

std::string try_outcome_name(TryOutcome outcome) {
  switch (outcome) {
    case TryOutcome::Accepted: return "accepted";
    case TryOutcome::Rattlers: return "rattlers";
    case TryOutcome::NotIsostatic: return "not_isostatic";
    case TryOutcome::NoPressureWindow: return "no_pressure_window";
    case TryOutcome::FireCap: return "fire_iteration_cap";
  }
  return "?";
}

double jamming_box_side(int n) { return std::cbrt(n * std::numbers::pi / (6 * 0.64)); }

namespace {

struct Try {
  TryOutcome outcome = TryOutcome::NoPressureWindow;
  Eigen::VectorXd x;
  double radius = 0;
  HertzState state;
  double max_force = 0;
  long fire_iterations = 0, size_changes = 0;
  int rattlers = 0;
};

Try jam_once(int n, double side, Random& random, const JammingParameters& p, int attempt,
             const JammingProgress& progress) {
  Try t;
  t.x.resize(3L * n);
  for (Eigen::Index k = 0; k < t.x.size(); ++k) t.x[k] = side * random.uniform();
  t.radius = std::cbrt(3 * p.initial_volume_fraction * side * side * side / (4 * std::numbers::pi * n));
  HertzSpheres system(Eigen::Vector3d::Constant(side), Eigen::VectorXd::Constant(n, t.radius), p.material);
  const auto forces = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) { system.forces(x, f); };
  const double volume = side * side * side;
  double step = p.initial_step;
  bool inflating = true;
  minimise::FireParameters step_fire = p.fire;
  if (p.step_iteration_cap > 0) step_fire.max_iterations = std::min(p.fire.max_iterations, p.step_iteration_cap);
  const auto relax = [&](const minimise::FireParameters& fire_parameters) {
    const auto fire = minimise::fire(t.x, forces, fire_parameters);
    t.fire_iterations += fire.iterations;
    t.max_force = fire.max_force;
    return fire;
  };
  const auto in_window = [&](double P) { return P > p.min_pressure && P < 2 * p.min_pressure; };
  for (;;) {
    auto fire = relax(step_fire);
    const bool capped = p.step_iteration_cap > 0 && fire.stop == minimise::FireStop::MaxIterations;
    if (!fire.converged() && !capped) { t.outcome = TryOutcome::FireCap; return t; }
    t.state = system.evaluate(t.x);
    if (capped && in_window(t.state.pressure)) {  // in the window but unrelaxed: relax fully, judge again
      fire = relax(p.fire);
      if (!fire.converged()) { t.outcome = TryOutcome::FireCap; return t; }
      t.state = system.evaluate(t.x);
    }
    const double P = t.state.pressure;
    const double phi = n * 4.0 / 3.0 * std::numbers::pi * std::pow(t.radius, 3) / volume;
    if (progress && !progress(attempt, t.size_changes, phi, P)) throw ComputationError("interrupted");
    if (fire.converged() && in_window(P)) break;
    if (t.size_changes >= p.max_size_changes || step < 1e-15) return t;  // NoPressureWindow
    const bool inflate = P <= p.min_pressure;
    if (inflate != inflating) step /= 2, inflating = inflate;  // halve eps_r at each reversal
    t.radius *= inflate ? 1 + step : 1 - step;
    system.set_radii(Eigen::VectorXd::Constant(n, t.radius));
    ++t.size_changes;
  }
  const auto rattler = find_rattlers(n, t.state.contacts);
  for (bool r : rattler) t.rattlers += r;
  if (t.rattlers > 0 && p.reject_rattlers)
    t.outcome = TryOutcome::Rattlers;
  else if (p.require_isostatic && static_cast<int>(t.state.contacts.size()) != isostatic_contacts(n))
    t.outcome = TryOutcome::NotIsostatic;
  else
    t.outcome = TryOutcome::Accepted;
  return t;
}

}  // namespace

JammingResult jam_spheres(int n, std::uint64_t seed, const JammingParameters& p, const JammingProgress& progress) {
  if (n < kMinJammingSpheres)
    throw UsageError("N = " + std::to_string(n) + " is too small: a periodic rattler-free jammed packing needs N >= " +
                     std::to_string(kMinJammingSpheres) + " (fewer spheres would each touch two images of another)");
  p.validate();
  const auto start = std::chrono::steady_clock::now();
  const double side = jamming_box_side(n);
  JammingResult result;
  for (int attempt = 0; attempt < p.max_tries; ++attempt) {
    Random random(seed, static_cast<std::uint64_t>(attempt));
    Try t = jam_once(n, side, random, p, attempt, progress);
    result.fire_iterations += t.fire_iterations;
    if (t.outcome != TryOutcome::Accepted) {
      ++result.rejected_tries;
      result.rejected_for_rattlers += t.outcome == TryOutcome::Rattlers;
      result.rejected_not_isostatic += t.outcome == TryOutcome::NotIsostatic;
      continue;
    }
    result.packing.box = Eigen::Vector3d::Constant(side);
    result.packing.positions = Eigen::Map<const mesh::VertexMatrix>(t.x.data(), n, 3);
    result.packing.radii = Eigen::VectorXd::Constant(n, t.radius);
    result.pressure = t.state.pressure;
    result.energy = t.state.energy;
    result.max_force = t.max_force;
    result.contacts = static_cast<int>(t.state.contacts.size());
    result.rattlers = t.rattlers;
    result.size_changes = t.size_changes;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  throw ComputationError("no acceptable jammed packing of " + std::to_string(n) + " spheres in " +
                         std::to_string(p.max_tries) + " tries (" + std::to_string(result.rejected_for_rattlers) +
                         " had rattlers, " + std::to_string(result.rejected_not_isostatic) +
                         " were not isostatic)");
}

}  // namespace cmp::spheres
