#include "spheremesh/annealing.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "io/csv.hpp"
#include "neighbours/mobile_cells.hpp"
#include "neighbours/monte_carlo_verlet_list.hpp"

#include <fmt/format.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace cmp::spheremesh {

using neighbours::MobileCells;
using neighbours::MonteCarloVerletList;

double AnnealingParameters::vertex_radius() const { return 2 * radius / std::sqrt(static_cast<double>(points)); }

void AnnealingParameters::validate() const {
  std::string problems;
  auto require = [&](bool ok, const std::string& what) {
    if (!ok) problems += (problems.empty() ? "" : "\n") + what;
  };
  require(points >= 4, fmt::format("number of points must be at least 4 (a tetrahedron), got {}", points));
  require(radius > 0 && std::isfinite(radius), fmt::format("radius must be positive, got {}", radius));
  require(t_min > 0 && std::isfinite(t_min), fmt::format("T_min must be positive, got {}", t_min));
  require(t_max >= t_min && std::isfinite(t_max), fmt::format("T_max ({}) must be at least T_min ({})", t_max, t_min));
  require(anneals >= 1, fmt::format("number of anneals must be at least 1, got {}", anneals));
  require(sweeps_per_anneal >= 0, fmt::format("sweeps per anneal must be non-negative, got {}", sweeps_per_anneal));
  require(epsilon > 0 && std::isfinite(epsilon), fmt::format("epsilon must be positive, got {}", epsilon));
  require(cutoff_sigmas > 0 && std::isfinite(cutoff_sigmas), fmt::format("cut-off must be positive, got {}", cutoff_sigmas));
  require(step_sigmas > 0 && std::isfinite(step_sigmas), fmt::format("trial step must be positive, got {}", step_sigmas));
  if (!problems.empty()) throw UsageError(problems);
}

double AnnealingParameters::temperature(int anneal) const {
  if (anneals == 1) return t_max;
  const double step = std::log(t_max / t_min) / (anneals - 1);
  return t_max * std::exp(-step * (anneal - 1));
}

double pair_energy(double r, double sigma, double cutoff, double epsilon) {
  if (r >= cutoff) return 0;
  return kLennardJonesPrefactor * epsilon * (std::pow(sigma / r, 8) - std::pow(sigma / cutoff, 8));
}

double total_energy_brute_force(const mesh::VertexMatrix& x, const AnnealingParameters& p) {
  const double sigma = p.sigma(), cutoff = p.cutoff_sigmas * sigma;
  double e = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    for (Eigen::Index j = i + 1; j < x.rows(); ++j) e += pair_energy((x.row(i) - x.row(j)).norm(), sigma, cutoff, p.epsilon);
  return e;
}

mesh::VertexMatrix random_points_on_sphere(int n, double radius, std::uint64_t seed) {
  Random rng(seed, /*stream=*/1);
  mesh::VertexMatrix x(n, 3);
  for (int i = 0; i < n; ++i) {
    double u, v, s;
    do {
      u = rng.uniform(-1, 1), v = rng.uniform(-1, 1), s = u * u + v * v;
    } while (s >= 1);
    const double w = 2 * std::sqrt(1 - s);
    x.row(i) << radius * u * w, radius * v * w, radius * (1 - 2 * s);
  }
  return x;
}

namespace {

// Verlet-list skin in units of sigma and the acceptance below which the list is used: the
// fastest of skins 0.4-2 and thresholds 0.2-0.5 over the full default schedule at N = 1000.
constexpr double kSkinSigmas = 1.0;
constexpr double kListAcceptance = 0.3;
constexpr int kRenumberEvery = 10;

// The pair law in reduced form: u / eps = (sigma^2/r^2)^4 - shift for r^2 < cutoff^2.
// Energies are summed in single precision: an energy difference needs a relative precision
// of about T / E_i ~ 1e-2 at the end of the schedule, and floats give 1e-7 at twice the speed.
struct PairLaw {
  float sigma2, cutoff2, shift, min_r2;  // min_r2 keeps (sigma/r)^8 finite for near-coincident points
};

// Eight floats as one value: GCC's vector extension, element-wise arithmetic that becomes one
// AVX2 register (or two SSE registers) with no change in rounding. Each slot's term always
// lands in the same lane and lanes are summed in a fixed order, so the energy is bit-identical
// whichever instruction set runs it: same seed, same mesh, on any x86-64.
typedef float Lanes __attribute__((vector_size(32)));
typedef float UnalignedLanes __attribute__((vector_size(32), aligned(4)));
typedef int LaneMask __attribute__((vector_size(32)));

[[gnu::always_inline]] inline Lanes load(const float* p) { return *reinterpret_cast<const UnalignedLanes*>(p); }

// Adds the pair terms of one cell's members (n a multiple of 8; empty slots are far away).
[[gnu::always_inline]] inline void add_cell(const float* x, const float* y, const float* z, int n,
                                            const float* p, const PairLaw& law, Lanes& acc) {
  for (int k = 0; k < n; k += 8) {
    const Lanes dx = p[0] - load(x + k), dy = p[1] - load(y + k), dz = p[2] - load(z + k);
    Lanes r2 = dx * dx + dy * dy + dz * dz;
    const LaneMask inside = r2 < law.cutoff2;
    r2 = r2 < law.min_r2 ? law.min_r2 : r2;
    const Lanes inv = law.sigma2 / r2, inv2 = inv * inv;
    const Lanes term = inv2 * inv2 - law.shift;
    acc += reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(term) & inside);
  }
}

double lane_sum(const Lanes& acc) {
  double sum = 0;
  for (int j = 0; j < 8; ++j) sum += acc[j];
  return sum;
}

// Energy (over eps) of a point at p with the members of the cells around `cell`.
[[gnu::target_clones("avx2", "default")]] double stencil_energy(const MobileCells& cells, int cell,
                                                                const double* p, const PairLaw& law) {
  Lanes acc = {};
  const float q[3] = {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
  cells.for_each_stencil_cell(cell, [&](int c) {
    const std::size_t base = static_cast<std::size_t>(c) * cells.capacity();
    add_cell(cells.xs() + base, cells.ys() + base, cells.zs() + base, cells.padded_count(c), q, law, acc);
  });
  return lane_sum(acc);
}

// Both energies of a trial move that stays in its cell, in one pass over the neighbours.
[[gnu::target_clones("avx2", "default")]] void stencil_energy_pair(const MobileCells& cells, int cell,
                                                                   const double* p_old, const double* p_new,
                                                                   const PairLaw& law, double& e_old,
                                                                   double& e_new) {
  Lanes acc_old = {}, acc_new = {};
  const float q_old[3] = {static_cast<float>(p_old[0]), static_cast<float>(p_old[1]), static_cast<float>(p_old[2])};
  const float q_new[3] = {static_cast<float>(p_new[0]), static_cast<float>(p_new[1]), static_cast<float>(p_new[2])};
  cells.for_each_stencil_cell(cell, [&](int c) {
    const std::size_t base = static_cast<std::size_t>(c) * cells.capacity();
    const float *x = cells.xs() + base, *y = cells.ys() + base, *z = cells.zs() + base;
    const int n = cells.padded_count(c);
    add_cell(x, y, z, n, q_old, law, acc_old);
    add_cell(x, y, z, n, q_new, law, acc_new);
  });
  e_old = lane_sum(acc_old);
  e_new = lane_sum(acc_new);
}

// Both energies of a trial move from particle i's Verlet list: partners' positions are
// gathered eight at a time by id, then the same branch-free arithmetic as add_cell.
[[gnu::target_clones("avx2", "default")]] void list_energy_pair(const MonteCarloVerletList& list, int i,
                                                                const double* p_old, const double* p_new,
                                                                const PairLaw& law, double& e_old, double& e_new) {
  Lanes acc_old = {}, acc_new = {};
  const float q_old[3] = {static_cast<float>(p_old[0]), static_cast<float>(p_old[1]), static_cast<float>(p_old[2])};
  const float q_new[3] = {static_cast<float>(p_new[0]), static_cast<float>(p_new[1]), static_cast<float>(p_new[2])};
  const int* ids = list.partner_ids() + list.begin(i);
  const float *xs = list.xs(), *ys = list.ys(), *zs = list.zs();
  const int n = list.padded_count(i);
  for (int k = 0; k < n; k += 8) {
    float gx[8], gy[8], gz[8];
    for (int j = 0; j < 8; ++j) gx[j] = xs[ids[k + j]], gy[j] = ys[ids[k + j]], gz[j] = zs[ids[k + j]];
    add_cell(gx, gy, gz, 8, q_old, law, acc_old);
    add_cell(gx, gy, gz, 8, q_new, law, acc_new);
  }
  e_old = lane_sum(acc_old);
  e_new = lane_sum(acc_new);
}

double total_energy(MobileCells& cells, const mesh::VertexMatrix& x, const PairLaw& law, double epsilon) {
  double e = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const int id = static_cast<int>(i);
    cells.hide(id);
    e += stencil_energy(cells, cells.cell_of_particle(id), x.row(i).data(), law);
    cells.restore(id, x(i, 0));
  }
  return 0.5 * kLennardJonesPrefactor * epsilon * e;
}

// Permutes the points of x (and the cells' copy) into cell order; ties keep their order.
void renumber_in_cell_order(mesh::VertexMatrix& x, MobileCells& cells) {
  const int n = static_cast<int>(x.rows());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return cells.cell_of_particle(a) < cells.cell_of_particle(b); });
  mesh::VertexMatrix sorted(n, 3);
  for (int k = 0; k < n; ++k) sorted.row(k) = x.row(order[k]);
  x.swap(sorted);
  cells.assign(x);
}

}  // namespace

AnnealingResult anneal_on_sphere(const AnnealingParameters& p, mesh::VertexMatrix start,
                                 const std::function<void(int, int)>& progress) {
  p.validate();
  const auto clock_start = std::chrono::steady_clock::now();
  AnnealingResult result;
  result.points = start.rows() ? std::move(start) : random_points_on_sphere(p.points, p.radius, p.seed);
  if (result.points.rows() != p.points) throw UsageError("starting configuration has the wrong number of points");
  mesh::VertexMatrix& x = result.points;
  const int n = p.points;
  const double sigma = p.sigma(), cutoff = p.cutoff_sigmas * sigma, step = p.step_sigmas * sigma;
  const PairLaw law{static_cast<float>(sigma * sigma), static_cast<float>(cutoff * cutoff),
                    static_cast<float>(std::pow(1.0 / p.cutoff_sigmas, 8)), static_cast<float>(1e-8 * sigma * sigma)};

  // A cube a little larger than the sphere, so that round-off never clamps a point.
  const double half = p.radius * (1 + 1e-9) + 1e-300;
  MobileCells cells(Eigen::Vector3d::Constant(-half), 2 * half, cutoff);
  cells.assign(x);
  MonteCarloVerletList list(cutoff, std::min(kSkinSigmas * sigma, cutoff / 1.5));
  bool list_current = false;
  double last_acceptance = 1;
  Random rng(p.seed);

  for (int anneal = 1; anneal <= p.anneals; ++anneal) {
    const double temperature = p.temperature(anneal);
    const double beta = 1.0 / temperature;
    long long accepted = 0, attempted = 0;
    // Every few temperatures, renumber the points in cell order so that neighbours sit close
    // in memory: moves pick points at random, and beyond a few thousand points the cache
    // decides the speed (+50% at N = 10242). Point order carries no meaning.
    const bool renumber = anneal % kRenumberEvery == 1;
    if (renumber) renumber_in_cell_order(x, cells);
    // Hot, fluid states keep particles wandering out of their skins, and the list would be
    // re-listed more than used: those temperatures use the cells alone.
    const bool use_list = last_acceptance < kListAcceptance;
    if (use_list && (renumber || !list_current)) list.build(x, cells);
    list_current = use_list;
    for (int sweep = 0; sweep < p.sweeps_per_anneal; ++sweep) {
      for (int t = 0; t < n; ++t) {
        const int i = static_cast<int>(rng.below(n));
        const double old[3] = {x(i, 0), x(i, 1), x(i, 2)};
        double trial[3] = {old[0] + rng.uniform(-step, step), old[1] + rng.uniform(-step, step),
                           old[2] + rng.uniform(-step, step)};
        const double threshold = rng.uniform();
        const double norm = std::sqrt(trial[0] * trial[0] + trial[1] * trial[1] + trial[2] * trial[2]);
        ++attempted;
        if (norm == 0) continue;
        for (double& c : trial) c *= p.radius / norm;  // project back onto the sphere

        // Both energies from i's Verlet list when the trial stays in its skin (nearly always
        // when cold), else from the cells around the old and new positions.
        double e_old, e_new;
        if (use_list && list.covers(i, trial)) {
          list_energy_pair(list, i, old, trial, law, e_old, e_new);
        } else {
          const int cell_old = cells.cell_of_particle(i);
          const int cell_new = cells.cell_of(Eigen::Vector3d(trial[0], trial[1], trial[2]));
          cells.hide(i);
          if (cell_old == cell_new) {
            stencil_energy_pair(cells, cell_old, old, trial, law, e_old, e_new);
          } else {
            e_old = stencil_energy(cells, cell_old, old, law);
            e_new = stencil_energy(cells, cell_new, trial, law);
          }
          cells.restore(i, old[0]);
        }
        // Metropolis (Algorithm 3): accept when p < min(exp(-dE/T), 1).
        const double delta = kLennardJonesPrefactor * p.epsilon * (e_new - e_old);
        if (delta <= 0 || threshold < std::exp(-delta * beta)) {
          x.row(i) << trial[0], trial[1], trial[2];
          cells.move(i, Eigen::Vector3d(trial[0], trial[1], trial[2]));
          if (use_list) list.move(i, x, cells);
          ++accepted;
        }
      }
    }
    last_acceptance = attempted ? static_cast<double>(accepted) / attempted : 0;
    result.attempted += attempted;
    result.accepted += accepted;
    AnnealStep s;
    s.temperature = temperature;
    s.acceptance = attempted ? static_cast<double>(accepted) / attempted : 0;
    s.energy_per_point = total_energy(cells, x, law, p.epsilon) / n;
    result.steps.push_back(s);
    if (progress) progress(anneal, p.anneals);
  }
  result.energy = total_energy(cells, x, law, p.epsilon);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

std::vector<std::pair<std::string, std::string>> annealing_fields(const AnnealingParameters& p,
                                                                  const AnnealingResult& r) {
  auto num = [](double x) { return io::format_number(x); };
  return {{"points", std::to_string(p.points)},
          {"radius", num(p.radius)},
          {"vertex_radius", num(p.vertex_radius())},
          {"seed", std::to_string(p.seed)},
          {"T_max", num(p.t_max)},
          {"T_min", num(p.t_min)},
          {"anneals", std::to_string(p.anneals)},
          {"sweeps_per_anneal", std::to_string(p.sweeps_per_anneal)},
          {"epsilon", num(p.epsilon)},
          {"cutoff_sigma", num(p.cutoff_sigmas)},
          {"step_sigma", num(p.step_sigmas)},
          {"acceptance", num(static_cast<double>(r.accepted) / static_cast<double>(std::max(1LL, r.attempted)))},
          {"final_energy_en", num(r.energy)}};
}

}  // namespace cmp::spheremesh
