#include "spheres/jamming.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/rattlers.hpp"

#include <algorithm>
#include <iterator>
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
  require(polydispersity >= 0 && polydispersity <= kMaxPolydispersity, "polydispersity must lie in [0, 0.25]");
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
// Accepted tries per try, measured with the default protocol (`shellpack jam -N n --seeds 1:4
// --threads 1`; README, shellpack): N = 50: 4 of 4 tries accepted; N = 128: 4 of 39 (31
// rejected for rattlers, 4 not isostatic); N = 256: 0 of 24 (seeds 1 and 2, --max-tries 12,
// all 24 with rattlers), and 1 of 63 with --keep-rattlers (seed 1). A packing with rattlers is
// almost never isostatic, so keeping rattlers alone changes little; allowing hyperstatic
// packings adds back the "not isostatic" rejections (N = 128: 8 of 39).
struct AcceptanceRow {
  int n;
  double both, rattlers_kept, hyperstatic_allowed;
};
constexpr AcceptanceRow kMeasuredAcceptance[] = {
    {50, 1.0, 1.0, 1.0},
    {128, 4.0 / 39, 4.0 / 39, 8.0 / 39},
    {256, 1.0 / 63, 1.0 / 63, 1.0 / 48},
};
}  // namespace

double expected_acceptance(int n, const JammingParameters& p) {
  const auto pick = [&](const AcceptanceRow& r) {
    if (p.reject_rattlers && p.require_isostatic) return r.both;
    if (p.require_isostatic) return r.rattlers_kept;
    if (p.reject_rattlers) return r.hyperstatic_allowed;
    return 1.0;
  };
  const auto& rows = kMeasuredAcceptance;
  const int count = static_cast<int>(std::size(rows));
  if (n <= rows[0].n) return pick(rows[0]);
  if (n >= rows[count - 1].n) return pick(rows[count - 1]);
  for (int k = 0; k + 1 < count; ++k)
    if (n <= rows[k + 1].n) {
      const double t = std::log(static_cast<double>(n) / rows[k].n) / std::log(static_cast<double>(rows[k + 1].n) / rows[k].n);
      return std::exp((1 - t) * std::log(pick(rows[k])) + t * std::log(pick(rows[k + 1])));
    }
  return pick(rows[count - 1]);
}

std::string acceptance_warning(int n, const JammingParameters& p) {
  const double a = expected_acceptance(n, p);
  if (!(a > 0) || 1 / a < 5) return "";
  std::string rules = p.reject_rattlers && p.require_isostatic ? "rattler-free and isostatic"
                      : p.require_isostatic                    ? "isostatic"
                                                               : "rattler-free";
  std::string advice = p.reject_rattlers && p.require_isostatic
                           ? "; --keep-rattlers --allow-hyperstatic together accept every try"
                       : p.require_isostatic ? "; --allow-hyperstatic too accepts every try"
                                             : "; --keep-rattlers too accepts every try";
  return "at N = " + std::to_string(n) + " only about 1 try in " + std::to_string(static_cast<long>(std::lround(1 / a))) +
         " ends " + rules + " (measured), so each packing takes that many random starts" + advice;
}

namespace {

struct Try {
  TryOutcome outcome = TryOutcome::NoPressureWindow;
  Eigen::VectorXd x;
  double radius = 0;  // the mean radius
  Eigen::VectorXd sizes;  // radius / mean radius of each sphere
  HertzState state;
  double max_force = 0;
  long fire_iterations = 0, size_changes = 0;
  int rattlers = 0;
};

Try jam_once(int n, double side, Random& random, const JammingParameters& p, JammingProgressInfo info,
             const JammingProgress& progress) {
  Try t;
  t.x.resize(3L * n);
  for (Eigen::Index k = 0; k < t.x.size(); ++k) t.x[k] = side * random.uniform();
  t.sizes = Eigen::VectorXd::Ones(n);
  if (p.polydispersity > 0) {  // drawn after the centres: a monodisperse run keeps its stream
    const double half_width = std::sqrt(3.0) * p.polydispersity;
    for (int i = 0; i < n; ++i) t.sizes[i] = random.uniform(1 - half_width, 1 + half_width);
    t.sizes /= t.sizes.mean();
  }
  const double size_cubes = t.sizes.array().cube().sum();  // n when monodisperse
  t.radius = std::cbrt(3 * p.initial_volume_fraction * side * side * side / (4 * std::numbers::pi * size_cubes));
  HertzSpheres system(Eigen::Vector3d::Constant(side), t.radius * t.sizes, p.material);
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
    const double phi = size_cubes * 4.0 / 3.0 * std::numbers::pi * std::pow(t.radius, 3) / volume;
    info.size_changes = t.size_changes, info.volume_fraction = phi, info.pressure = P;
    if (progress && !progress(info)) throw ComputationError("interrupted");
    if (fire.converged() && in_window(P)) break;
    if (t.size_changes >= p.max_size_changes || step < 1e-15) return t;  // NoPressureWindow
    const bool inflate = P <= p.min_pressure;
    if (inflate != inflating) step /= 2, inflating = inflate;  // halve eps_r at each reversal
    t.radius *= inflate ? 1 + step : 1 - step;
    system.set_radii(t.radius * t.sizes);
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
    JammingProgressInfo info;
    info.attempt = attempt;
    info.rejected_for_rattlers = result.rejected_for_rattlers;
    info.rejected_not_isostatic = result.rejected_not_isostatic;
    info.rejected_no_pressure_window = result.rejected_no_pressure_window;
    info.rejected_fire_cap = result.rejected_fire_cap;
    Try t = jam_once(n, side, random, p, info, progress);
    result.fire_iterations += t.fire_iterations;
    if (t.outcome != TryOutcome::Accepted) {
      ++result.rejected_tries;
      result.rejected_for_rattlers += t.outcome == TryOutcome::Rattlers;
      result.rejected_not_isostatic += t.outcome == TryOutcome::NotIsostatic;
      result.rejected_no_pressure_window += t.outcome == TryOutcome::NoPressureWindow;
      result.rejected_fire_cap += t.outcome == TryOutcome::FireCap;
      continue;
    }
    result.packing.box = Eigen::Vector3d::Constant(side);
    result.packing.positions = Eigen::Map<const mesh::VertexMatrix>(t.x.data(), n, 3);
    result.packing.radii = t.radius * t.sizes;
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
                         " were not isostatic, " + std::to_string(result.rejected_no_pressure_window) +
                         " missed the pressure window, " + std::to_string(result.rejected_fire_cap) +
                         " hit the FIRE iteration cap)");
}

}  // namespace cmp::spheres
