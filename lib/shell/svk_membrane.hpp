#pragma once
// The St Venant-Kirchhoff membrane on linear triangles, the thesis's "FEM" (B.2.2, B.28-B.34),
// in Delingette's triangular biquadratic springs form. Per rest triangle T with edges i = 0, 1, 2
// (edge i opposite corner i), rest lengths L_i, deformed lengths l_i, rest angles alpha_i and
// rest area A, with d_i = l_i^2 - L_i^2 (B.34):
//   E_T = sum_i (k_i/4) d_i^2 + sum over the 3 unordered edge pairs {i, j} of (c_ij/2) d_i d_j
//   k_i  = Y (2 cot^2 alpha_i + 1 - nu) / (16 (1 - nu^2) A)            (B.32)
//   c_ij = Y (2 cot alpha_i cot alpha_j + nu - 1) / (16 (1 - nu^2) A)  (B.33)
// This equals A times the energy density of B.28, (lambda/2)(tr G)^2 + mu tr(G^2) of the
// Green-Lagrange strain G, with the 2D Lame constants lambda = Y nu/(1 - nu^2) and
// mu = Y/(2 (1 + nu)), Y = E t (B.29's mu/2 is a misprint). Exact at any strain.
// Evaluated as a structure-of-arrays loop over the triangles on all threads
// (element_assembly.hpp: the same bits for any thread count).
#include "shell/element_assembly.hpp"
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

class SvkMembrane final : public EnergyTerm {
 public:
  // Throws cmp::UsageError for bad parameters or a bad rest mesh.
  SvkMembrane(const mesh::TriMesh& rest, const MaterialParameters& p);
  std::string name() const override { return "svk"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }

 private:
  // Per triangle (columns of #F doubles: column i of each array at i #F): rest squared
  // lengths L_i^2, tensile k_i, and the angular c of the pair opposite each index (c[0] for
  // the pair {1, 2}, and so on). The corners are the assembly's.
  long vertex_count_;
  ElementAssembly assembly_;
  std::vector<double> rest_l2_, k_, c_;
};

}  // namespace cmp::shell
