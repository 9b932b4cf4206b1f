#pragma once
// Energy, forces and torques of a set of budding cells (thesis S3.2-S3.4): a contact law
// between every pair of overlapping lobes of different cells, in a rectangular box that is
// periodic (Chapter 3) or not (the walls of a chamber are a separate term), optionally with
// Lees-Edwards images for simple shear. Shared by every model built on lib/cells2d.
//
// The lobe pairs come from a Verlet list over the lobe centres (lib/neighbours), kept as a half
// list of the pairs that can touch before the next rebuild: other cell, j > i, closer than
// their radii plus the law's range and the skin. It is rebuilt when a lobe has moved more than a
// quarter of the skin, or grown by more than a quarter of it, since the build (so two lobes can
// close the skin only together), so a minimisation or a chamber run pays for the neighbour
// search a few times, not at every force evaluation. The force loop is a template instantiated
// per contact law; it visits the pairs in the full list's order, so the half list changes no
// bit of the sums. Serial and deterministic: a sweep runs many colonies in parallel instead.
#include "cells2d/cell.hpp"
#include "cells2d/contact_law.hpp"
#include "core/minimum_image.hpp"
#include "neighbours/neighbour_list.hpp"

#include <Eigen/Core>

#include <cmath>
#include <memory>
#include <span>
#include <vector>

namespace cmp::cells2d {

// The simulation box [0, lx) x [0, ly) [sigma].
struct Domain {
  double lx = 10, ly = 10;
  bool periodic = true;  // along x and y
  // Lees-Edwards simple shear strain (periodic only): the image of a cell across the y
  // boundary is shifted by shear * ly along x, so x -> x + shear * y is an affine state.
  double shear = 0;

  // r_a - r_b reduced to the nearest image (Lees-Edwards when sheared).
  Eigen::Vector2d separation(Eigen::Vector2d d) const {
    if (periodic) {
      const double ny = std::nearbyint(d[1] / ly);
      d[1] -= ny * ly;
      d[0] -= ny * shear * ly;
      d[0] = minimum_image(d[0], lx);
    }
    return d;
  }
};

// One interacting lobe pair: lobes a < b (lobe 2i mother, 2i + 1 bud of cell i).
struct Contact {
  int a, b;
  Eigen::Vector2d d;  // centre of a minus centre of b (nearest image) [sigma]
  double distance;    // |d| [sigma]
  double overlap;     // delta [sigma]: > 0 for touching lobes, in (-range, 0] within an attractive law's reach
  double force;       // dV/d delta [k sigma], > 0 repulsive; on a it is force * d / distance
};

class ContactEngine {
 public:
  // Throws cmp::UsageError when the box is smaller than 2 (cutoff + skin) along a periodic
  // axis or not positive. skin [sigma]: the Verlet list's margin.
  ContactEngine(const Domain& domain, const ContactLawStyle& law, const LawParameters& parameters = {},
                double skin = 0.3);

  const Domain& domain() const { return domain_; }
  const ContactLawStyle& law() const { return *law_; }
  const LawParameters& law_parameters() const { return parameters_; }
  // The law's energy and force of an overlap, with this engine's parameters.
  double pair_energy(double overlap) const { return law_->energy(overlap, parameters_); }
  double pair_force(double overlap) const { return law_->force(overlap, parameters_); }
  // Changes the Lees-Edwards strain (by at most ~1e-3: the list keeps a margin for it); the pairs
  // are found anew at the next evaluation.
  void set_shear(double strain) {
    domain_.shear = strain;
    pairs_stale_ = true;
  }

  // Energy V [k sigma^2]; force (3 per cell, 3 * cells.size()) receives F_x, F_y [k sigma]
  // and the torque T = -dV/dtheta [k sigma^2] of every cell. The hot path.
  double evaluate(const std::vector<Cell>& cells, double* force);
  // Energy alone [k sigma^2].
  double energy(const std::vector<Cell>& cells);

  // Calls f(const Contact&) for every interacting pair of lobes of different cells, once: the
  // overlapping ones, and for an attractive law those within its range.
  template <class F>
  void for_each_contact(const std::vector<Cell>& cells, F&& f);

  long list_builds() const { return list_.builds(); }
  // The cells were renumbered (a cell removed or inserted without changing their count): find
  // the pairs anew at the next evaluation.
  void renumbered() { pairs_stale_ = true; }
  // The pairs that may interact before the next rebuild: for lobe i, pair_j_[pair_start_[i] ..
  // pair_start_[i + 1]).
  std::span<const int> candidates_of(int i) const {
    return {pair_j_.data() + pair_start_[static_cast<std::size_t>(i)],
            pair_j_.data() + pair_start_[static_cast<std::size_t>(i) + 1]};
  }

  // The lobes as last placed by evaluate, energy or for_each_contact: how many, their centres,
  // radii and offsets from their cell's centre of mass (what walls need, without recomputing the
  // cells' orientations).
  int lobe_count() const { return static_cast<int>(radius_.size()); }
  Eigen::Vector2d lobe_position(int l) const { return {lobes_(l, 0), lobes_(l, 1)}; }
  double lobe_radius(int l) const { return radius_[static_cast<std::size_t>(l)]; }
  Eigen::Vector2d lobe_offset(int l) const {
    return {offset_x_[static_cast<std::size_t>(l)], offset_y_[static_cast<std::size_t>(l)]};
  }

  // The force loop for one law (contact_kernel.hpp; a registered law points at it).
  template <class Law>
  static double kernel(const ContactEngine& engine, const std::vector<Cell>& cells, double* force);

 private:
  // Lobe centres and diameters from the cells; rebuilds the Verlet list when needed.
  void place_lobes(const std::vector<Cell>& cells);
  template <class Law>
  double evaluate_with(const std::vector<Cell>& cells, double* force) const;

  // The half list from a fresh Verlet list.
  void build_pairs();

  Domain domain_;
  const ContactLawStyle* law_;
  LawParameters parameters_;
  double range_;  // law_->range(parameters_)
  double skin_;
  neighbours::NeighbourList list_;
  std::vector<int> pair_start_, pair_j_;
  mesh::VertexMatrix built_at_;       // lobe centres when the pairs were built
  std::vector<double> built_radius_;  // and their radii
  bool pairs_stale_ = true;
  mesh::VertexMatrix lobes_;            // 2N by 3 (z = 0)
  std::vector<double> radius_;          // 2N lobe radii
  std::vector<double> offset_x_, offset_y_;  // 2N lobe centre - cell centre
};

// ---- templates ----

template <class F>
void ContactEngine::for_each_contact(const std::vector<Cell>& cells, F&& f) {
  place_lobes(cells);
  const int lobes = static_cast<int>(radius_.size());
  for (int i = 0; i < lobes; ++i) {
    const Eigen::Vector2d pi(lobes_(i, 0), lobes_(i, 1));
    for (int j : candidates_of(i)) {
      const Eigen::Vector2d d = domain_.separation(pi - Eigen::Vector2d(lobes_(j, 0), lobes_(j, 1)));
      const double contact = radius_[i] + radius_[j], reach = contact + range_, r2 = d.squaredNorm();
      if (r2 >= reach * reach || r2 == 0) continue;
      const double r = std::sqrt(r2), overlap = contact - r;
      f(Contact{i, j, d, r, overlap, pair_force(overlap)});
    }
  }
}

}  // namespace cmp::cells2d
