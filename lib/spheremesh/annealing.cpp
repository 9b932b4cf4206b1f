#include "spheremesh/annealing.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"
#include "neighbours/mobile_cells.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <string>

namespace cmp::spheremesh {

using neighbours::MobileCells;

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
  return epsilon * (std::pow(sigma / r, 8) - std::pow(sigma / cutoff, 8));
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

// The pair law in reduced form: u / eps = (sigma^2/r^2)^4 - shift for r^2 < cutoff^2.
struct PairLaw {
  double sigma2, cutoff2, shift;
};

// Adds the pair terms of one cell's members to four fixed lanes. The lane of each term is
// fixed by its slot, and lanes are summed in a fixed order afterwards, so the result does not
// depend on how (or whether) the compiler vectorises: same seed, same mesh, on any x86-64.
[[gnu::always_inline]] inline void add_cell(const double* x, const double* y, const double* z, int n,
                                            double px, double py, double pz, const PairLaw& law,
                                            double acc[4]) {
  for (int k = 0; k < n; k += 4)
    for (int j = 0; j < 4; ++j) {
      const double dx = px - x[k + j], dy = py - y[k + j], dz = pz - z[k + j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double inv = law.sigma2 / r2, inv2 = inv * inv;
      acc[j] += r2 < law.cutoff2 ? inv2 * inv2 - law.shift : 0.0;
    }
}

// Energy (over eps) of a point at p with the members of the cells around `cell`.
[[gnu::target_clones("avx2", "default")]] double stencil_energy(const MobileCells& cells, int cell,
                                                                const double* p, const PairLaw& law) {
  double acc[4] = {0, 0, 0, 0};
  cells.for_each_stencil_cell(cell, [&](int c) {
    const std::size_t base = static_cast<std::size_t>(c) * cells.capacity();
    add_cell(cells.xs() + base, cells.ys() + base, cells.zs() + base, cells.padded_count(c), p[0], p[1],
             p[2], law, acc);
  });
  return (acc[0] + acc[1]) + (acc[2] + acc[3]);
}

// Both energies of a trial move that stays in its cell, in one pass over the neighbours.
[[gnu::target_clones("avx2", "default")]] void stencil_energy_pair(const MobileCells& cells, int cell,
                                                                   const double* p_old, const double* p_new,
                                                                   const PairLaw& law, double& e_old,
                                                                   double& e_new) {
  double acc_old[4] = {0, 0, 0, 0}, acc_new[4] = {0, 0, 0, 0};
  cells.for_each_stencil_cell(cell, [&](int c) {
    const std::size_t base = static_cast<std::size_t>(c) * cells.capacity();
    const double *x = cells.xs() + base, *y = cells.ys() + base, *z = cells.zs() + base;
    const int n = cells.padded_count(c);
    add_cell(x, y, z, n, p_old[0], p_old[1], p_old[2], law, acc_old);
    add_cell(x, y, z, n, p_new[0], p_new[1], p_new[2], law, acc_new);
  });
  e_old = (acc_old[0] + acc_old[1]) + (acc_old[2] + acc_old[3]);
  e_new = (acc_new[0] + acc_new[1]) + (acc_new[2] + acc_new[3]);
}

double total_energy(MobileCells& cells, const mesh::VertexMatrix& x, const PairLaw& law, double epsilon) {
  double e = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const int id = static_cast<int>(i);
    cells.hide(id);
    e += stencil_energy(cells, cells.cell_of_particle(id), x.row(i).data(), law);
    cells.restore(id, x(i, 0));
  }
  return 0.5 * epsilon * e;
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
  const PairLaw law{sigma * sigma, cutoff * cutoff, std::pow(1.0 / p.cutoff_sigmas, 8)};

  // A cube a little larger than the sphere, so that round-off never clamps a point.
  const double half = p.radius * (1 + 1e-9) + 1e-300;
  MobileCells cells(Eigen::Vector3d::Constant(-half), 2 * half, cutoff);
  cells.assign(x);
  Random rng(p.seed);

  for (int anneal = 1; anneal <= p.anneals; ++anneal) {
    const double temperature = p.temperature(anneal);
    const double beta = 1.0 / temperature;
    long long accepted = 0, attempted = 0;
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

        const int cell_old = cells.cell_of_particle(i);
        const int cell_new = cells.cell_of(Eigen::Vector3d(trial[0], trial[1], trial[2]));
        double e_old, e_new;
        cells.hide(i);
        if (cell_old == cell_new) {
          stencil_energy_pair(cells, cell_old, old, trial, law, e_old, e_new);
        } else {
          e_old = stencil_energy(cells, cell_old, old, law);
          e_new = stencil_energy(cells, cell_new, trial, law);
        }
        cells.restore(i, old[0]);
        // Metropolis (Algorithm 3): accept when p < min(exp(-dE/T), 1).
        const double delta = p.epsilon * (e_new - e_old);
        if (delta <= 0 || threshold < std::exp(-delta * beta)) {
          x.row(i) << trial[0], trial[1], trial[2];
          cells.move(i, Eigen::Vector3d(trial[0], trial[1], trial[2]));
          ++accepted;
        }
      }
    }
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

}  // namespace cmp::spheremesh
