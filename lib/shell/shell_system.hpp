#pragma once
// A shell system: one rest mesh holding one or many shells (its connected components), one
// flat state vector of every vertex position, the energy terms acting on it, and the vertices
// held fixed (clamped edges). The minimisers and integrators (relax.hpp) see only the state
// and the total force; the packings of many shells use the same object.
//
//   ShellSystem s(rest);                                  // state = rest positions
//   s.add(stretching_style("svk").make(rest, material));
//   s.add(pressure_style("turgor").make(rest, {2.5e5}));
//   relax(s, parameters);                                 // FIRE to equilibrium
#include "shell/energy_term.hpp"
#include "shell/hertz_contacts.hpp"
#include "shell/shell_contact_term.hpp"
#include "shell/shell_partition.hpp"
#include "shell/turgor_pressure.hpp"

#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace cmp::shell {

// A state vector as the terms take it.
inline std::span<const double> span_of(const Eigen::VectorXd& v) { return {v.data(), static_cast<std::size_t>(v.size())}; }
inline std::span<double> span_of(Eigen::VectorXd& v) { return {v.data(), static_cast<std::size_t>(v.size())}; }

class ShellSystem {
 public:
  // Throws cmp::UsageError for a bad rest mesh: an index out of range, a non-finite position,
  // a degenerate triangle, a vertex in no face.
  explicit ShellSystem(mesh::TriMesh rest);

  const mesh::TriMesh& rest() const { return rest_; }
  const ShellPartition& shells() const { return shells_; }
  long vertex_count() const { return rest_.V.rows(); }

  // Adds a term built on this rest mesh (throws std::invalid_argument for another size).
  void add(std::unique_ptr<EnergyTerm> term);
  const std::vector<std::unique_ptr<EnergyTerm>>& terms() const { return terms_; }
  // The first term of each kind, or nullptr.
  TurgorPressure* pressure() const { return pressure_; }
  WallContacts* walls() const { return walls_; }
  ShellContactTerm* contacts() const { return contacts_; }  // the contacts between shells

  // Holds these vertices where they are: their forces read zero and no integrator moves them.
  void fix(const std::vector<int>& vertices);
  const std::vector<char>& fixed() const { return fixed_; }

  // The state: 3 #V positions (x0 y0 z0 x1 ...), the rest positions at construction.
  Eigen::VectorXd x;

  // The total energy at y (sum of every term).
  double energy(const Eigen::VectorXd& y) const;
  // f = -grad E at y, zero on the fixed vertices (f is resized).
  void forces(const Eigen::VectorXd& y, Eigen::VectorXd& f) const;
  // The same without one term's part (a constraint that projects that part out anyway).
  void forces_without(const EnergyTerm* left_out, const Eigen::VectorXd& y, Eigen::VectorXd& f) const;
  // Each term's energy at y, in the order of terms().
  std::vector<double> term_energies(const Eigen::VectorXd& y) const;

  // Every interior edge as a hinge (x0, x1, x2, x3) as in DihedralHinges, with its rest angle:
  // for the fold check of folded_hinges().
  const std::vector<int>& hinges() const { return hinge_quads_; }
  const std::vector<double>& rest_hinge_angles() const { return hinge_rest_; }

 private:
  mesh::TriMesh rest_;
  ShellPartition shells_;
  std::vector<std::unique_ptr<EnergyTerm>> terms_;
  TurgorPressure* pressure_ = nullptr;
  WallContacts* walls_ = nullptr;
  ShellContactTerm* contacts_ = nullptr;
  std::vector<char> fixed_;
  std::vector<int> hinge_quads_;
  std::vector<double> hinge_rest_;
};

// The number of hinges folded over at y: the angle between the normals of two neighbouring
// faces differs from its rest value by more than 120 degrees, i.e. one element has turned
// inside out (a pressure the membrane cannot hold, a collapsed buckle).
long folded_hinges(const ShellSystem& s, const Eigen::VectorXd& y);

}  // namespace cmp::shell
