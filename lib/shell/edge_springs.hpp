#pragma once
// Harmonic springs on the mesh edges (thesis B.2.2, B.18-B.19):
//   E = sum over edges e of (1/2) k_e (|x_j - x_i| - L_e)^2,
// rest lengths L_e from the reference mesh, with the factor 1/2 of B.20 and B.25 (the force of
// B.19 is its gradient). The spring constants k_e come from one of three rules, all in terms of
// the stretching modulus Y = E t:
//   SeungNelson  k = sqrt(3) Y / 2 on every edge (B.22: Y = 2k/sqrt(3), nu fixed at 1/3)
//   Kot          k = 2Y/(1 - nu) A_0 / sum_e L_e^2 on every edge (B.26, A_0 the rest area)
//   VanGelder    k_e = sum over the rest triangles T holding e of
//                Y/(1 + nu) A_T/|c|^2 + Y nu/(1 - nu^2) (|a|^2 + |b|^2 - |c|^2)/(8 A_T) (B.27)
// Whatever the rule, a central-force spring mesh has nu = 1/3 (B.2.2).
// Evaluated as a loop over the edges on all threads (element_assembly.hpp: the same bits for
// any thread count).
#include "shell/element_assembly.hpp"
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

enum class SpringConstants { SeungNelson, Kot, VanGelder };

// The spring constant of each edge of mesh::edge_topology(rest.F).edges (same order).
std::vector<double> edge_spring_constants(const mesh::TriMesh& rest, const MaterialParameters& p, SpringConstants rule);

class EdgeSprings final : public EnergyTerm {
 public:
  // Throws cmp::UsageError for bad parameters or a bad rest mesh.
  EdgeSprings(const mesh::TriMesh& rest, const MaterialParameters& p, SpringConstants rule, std::string name);
  std::string name() const override { return name_; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }
  // Per edge: end vertices (2 per edge), rest length, spring constant.
  const std::vector<int>& edge_vertices() const { return ends_; }
  const std::vector<double>& rest_lengths() const { return rest_; }
  const std::vector<double>& spring_constants() const { return k_; }

 private:
  std::string name_;
  long vertex_count_;
  std::vector<int> ends_;
  std::vector<double> rest_, k_;
  ElementAssembly assembly_;
};

}  // namespace cmp::shell
