#pragma once
// Simulated-annealing Monte Carlo of N points on a sphere (thesis A.2.2, Algorithms 1-3).
#include "mesh/tri_mesh.hpp"
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace cmp::spheremesh {

// Every parameter of A.2.2, with the thesis's values as defaults.
struct AnnealingParameters {
  int points = 0;               // N >= 4
  double radius = 1.0;          // R of the sphere
  double t_max = 1000.0;        // first temperature [energy units]
  double t_min = 0.1;           // last temperature
  int anneals = 200;            // n_anneals temperatures, T_i = T_max exp(-dT (i-1))
  int sweeps_per_anneal = 100;  // n_mc; a sweep is N trial moves of randomly chosen nodes
  double epsilon = 1.0;         // energy scale of the LJ-8 repulsion
  double cutoff_sigmas = 3.0;   // r_c in units of sigma = 2 r_v
  // Trial displacement: uniform in [-s, s] per Cartesian axis, then back onto the sphere. The
  // thesis is silent (Algorithm 2 is lost); its author's public code draws +-0.25 sigma.
  double step_sigmas = 0.25;
  std::uint64_t seed = 1;

  // Vertex size r_v from N pi r_v^2 = 4 pi R^2.
  double vertex_radius() const;
  double sigma() const { return 2 * vertex_radius(); }
  // Throws cmp::UsageError naming every bad value.
  void validate() const;
  // The temperature of anneal i = 1..anneals.
  double temperature(int anneal) const;
};

// What happened at one temperature.
struct AnnealStep {
  double temperature = 0;
  double acceptance = 0;         // accepted / attempted trial moves
  double energy_per_point = 0;   // at the end of the step
};

struct AnnealingResult {
  mesh::VertexMatrix points;     // N by 3, on the sphere
  std::vector<AnnealStep> steps;
  long long attempted = 0, accepted = 0;
  double energy = 0;             // final total pair energy
  double seconds = 0;            // wall time of the Monte Carlo
};

// The prefactor of Lennard-Jones potentials, 4 eps [(sigma/r)^2n - (sigma/r)^n]. A.2.2 says
// "the repulsive part of the Lennard-Jones-8 potential with eps = 1"; with the factor 4 (and
// only with a factor of 4 to 8) the T_end dependence of Table A.6 is reproduced, while
// eps (sigma/r)^8 alone gives meshes far worse than the thesis's at T_end = 1 to 100.
inline constexpr double kLennardJonesPrefactor = 4.0;

// Pair energy u(r) = 4 eps [(sigma/r)^8 - (sigma/r_c)^8] for r < r_c, 0 beyond: the repulsive
// part of the LJ 8-4 potential, shifted to vanish at the cut-off (A.2.2).
double pair_energy(double r, double sigma, double cutoff, double epsilon);

// Total pair energy of points by brute force, O(N^2): the reference the fast path is tested on.
double total_energy_brute_force(const mesh::VertexMatrix& points, const AnnealingParameters& p);

// Uniform random points on the sphere (Marsaglia), the starting state of A.2.2.
mesh::VertexMatrix random_points_on_sphere(int n, double radius, std::uint64_t seed);

// Runs the schedule from `start` (N by 3 on the sphere; random_points_on_sphere() when empty).
// The returned points are renumbered (in cell order, for the cache): row i of the result is
// not the point that started in row i.
// O(N) per sweep through linked cells. A Markov chain is sequential, so this is one thread;
// run independent meshes in parallel. progress(i, anneals) is called after each temperature.
AnnealingResult anneal_on_sphere(const AnnealingParameters& p, mesh::VertexMatrix start = {},
                                 const std::function<void(int, int)>& progress = {});

// The parameters and outcome of a run as (key, value) pairs, for the "# key=value" lines of
// the files it produces (energies in units of epsilon's energy unit: "_en").
std::vector<std::pair<std::string, std::string>> annealing_fields(const AnnealingParameters& p,
                                                                  const AnnealingResult& r);

}  // namespace cmp::spheremesh
