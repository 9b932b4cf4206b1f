#pragma once
// Hertzian spheres in a periodic box: forces, energy, pressure and contacts over a Verlet
// pair list built by linked cells (O(N) per step), the force field that FIRE relaxes.
//
//   HertzSpheres system(box, radii, material);
//   minimise::fire(x, [&](auto& x, auto& f) { system.forces(x, f); }, params);
//   auto state = system.evaluate(x);   // energy, pressure, contacts
//
// Positions are a flat vector (x0, y0, z0, x1, ...): the memory of a row-major #N by 3
// VertexMatrix. Particles may leave the box; the minimum image takes care of it.
#include "core/minimum_image.hpp"
#include "forcefield/hertz.hpp"

#include <Eigen/Core>

#include <vector>

namespace cmp::spheres {

// One touching pair (h > 0): force on i is +force * branch / |branch|, on j the opposite.
struct Contact {
  int i = 0, j = 0;         // i < j
  Eigen::Vector3d branch;   // x_i - x_j, minimum image
  double overlap = 0;       // h = R_i + R_j - |branch|
  double force = 0;         // Hertz force magnitude
};

struct HertzState {
  double energy = 0;    // sum of pair energies
  double pressure = 0;  // P = (1/3V) sum_pairs |r_ij| F_ij (virial, thesis 5.5.1; > 0 when compressed)
  std::vector<Contact> contacts;  // ordered by (i, j)
};

class HertzSpheres {
 public:
  // box: side lengths of the periodic box; radii: one per sphere. skin: extra reach of the
  // pair list, as a fraction of the mean diameter. Throws cmp::UsageError for a bad box,
  // radii or material.
  HertzSpheres(const Eigen::Vector3d& box, const Eigen::VectorXd& radii, const HertzMaterial& material,
               double skin = 0.2);

  // New radii (same count); the pair list is rebuilt at the next call.
  void set_radii(const Eigen::VectorXd& radii);
  const Eigen::VectorXd& radii() const { return radii_; }
  const Eigen::Vector3d& box() const { return box_; }
  int size() const { return static_cast<int>(radii_.size()); }

  // f = forces on every sphere (flat, like x). Rebuilds the pair list when some sphere moved
  // more than skin/2 since the last build. Deterministic for any thread count: from
  // kParallelForceSpheres spheres on, the pair list is cut into kForceChunks fixed chunks,
  // each summed into its own buffer by whichever thread takes it, and the buffers are added
  // in chunk order; below it one serial pass. Throws cmp::ComputationError when a sphere is
  // wider than half the box (it would touch two images of another: N too small).
  void forces(const Eigen::VectorXd& x, Eigen::VectorXd& f);
  // Below this many spheres an iteration is too short to pay for a fork/join.
  static constexpr int kParallelForceSpheres = 2048;
  // Chunks of the pair list: a fixed number, so the sums do not depend on the threads.
  static constexpr int kForceChunks = 4;
  // Energy, pressure and the list of contacts at x.
  HertzState evaluate(const Eigen::VectorXd& x);

  long list_builds() const { return builds_; }

 private:
  void ensure_list(const Eigen::VectorXd& x);
  void build_list(const Eigen::VectorXd& x);
  // Adds the forces of pairs [begin, end) of the list to f (flat, zeroed by the caller).
  void add_pair_forces(const double* x, std::size_t begin, std::size_t end, double* f) const;
  Eigen::Vector3d minimum_image(const double* xi, const double* xj) const {
    Eigen::Vector3d d;
    for (int a = 0; a < 3; ++a) {
      d[a] = xi[a] - xj[a];
      d[a] = cmp::minimum_image(d[a], box_[a], inverse_box_[a]);
    }
    return d;
  }

  Eigen::Vector3d box_, inverse_box_;
  Eigen::VectorXd radii_;
  HertzMaterial material_;
  double skin_fraction_, skin_ = 0;
  bool stale_ = true;
  long builds_ = 0;
  Eigen::VectorXd reference_;  // positions at the last build
  // The pair list, structure of arrays, ordered by (i, j) with i < j; contact distance and
  // Hertz prefactor of each pair precomputed.
  std::vector<int> first_, second_;
  std::vector<double> reach_, prefactor_;
  std::vector<double> chunk_forces_;  // kForceChunks buffers of 3N forces (large N only)
};

}  // namespace cmp::spheres
