#pragma once
// Bending springs on the dihedral hinges of the interior edges, with a curved rest state
// (thesis B.2.3, B.37-B.44). For the hinge of edge e between faces T0 and T1, with phi_e the
// signed angle between their unit normals (0 for a flat pair) and phi_e^0 its rest value:
//   E = sum_e kappa_e (1 - cos(phi_e - phi_e^0)),  kappa_e = 3 |e|^2 kappa / A_e
// |e| the rest edge length, A_e the rest area of T0 and T1 together, kappa = E t^3/(12(1-nu^2)).
// B.39 prints 1 + cos(theta - theta_0) in terms of the angle theta = pi - phi between the
// faces; written in phi it is 1 - cos, a minimum at rest, and B.40's force is its gradient.
// (B.38's right-hand side, (2 cos(theta/2))^2, is twice 1 + cos(theta); its left side is used.)
// Calibration against a flat rest (tests/shell/test_dihedral_hinges.cpp): on icosahedral spheres
// Local stores 8 pi kappa within 2 %; on a cylinder inscribed with equilateral triangles Uniform
// gives B.36's kappa = (sqrt(3)/2) kappa~ within 2 %, while Local there measures about 3 kappa
// (the two calibrations disagree: which suits the B.5 plate benchmarks is still to be shown).
// The gradient of phi is that of B.41-B.44: |e|/(2A) n on the two wing vertices, and on the
// hinge's ends the combination that keeps the total force and torque zero.
// Boundary edges carry no hinge. The mesh must be consistently oriented.
// Evaluated without trigonometric functions: cos phi and sin phi come from the normals
// (N0 . N1 and (N0 x N1) . e/|e| over |N0||N1|), and cos and sin of the rest angle are stored,
// so sin(phi - phi0) and 1 - cos(phi - phi0) (as sin^2/(1 + cos) where cos > 0: no
// cancellation near rest) cost products only; a structure-of-arrays loop over the hinges on
// all threads (element_assembly.hpp: the same bits for any thread count).
// HingeStiffness::Uniform gives every hinge kappa_e = 2 kappa / sqrt(3): the normal-vector
// springs of B.35, kappa~ sum (1 - n_a . n_b), with B.36's cylinder calibration
// kappa = (sqrt(3)/2) kappa~, here with a curved rest state as in B.39.
#include "shell/element_assembly.hpp"
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

enum class HingeStiffness {
  Local,    // kappa_e = 3 |e|^2 kappa / A_e (B.38)
  Uniform,  // kappa_e = 2 kappa / sqrt(3) (B.35-B.36)
};

class DihedralHinges final : public EnergyTerm {
 public:
  // Throws cmp::UsageError for bad parameters, a bad rest mesh, or an interior edge whose two
  // faces run it the same way (inconsistent orientation).
  DihedralHinges(const mesh::TriMesh& rest, const MaterialParameters& p,
                 HingeStiffness stiffness = HingeStiffness::Local, std::string name = "hinge");
  std::string name() const override { return name_; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }
  // Per hinge: x0, x1 (the edge, run x0 -> x1 by T0), x2 (T0's third corner), x3 (T1's).
  const std::vector<int>& hinge_vertices() const { return quad_; }
  const std::vector<double>& rest_angles() const { return phi0_; }
  const std::vector<double>& stiffnesses() const { return kappa_; }

 private:
  std::string name_;
  long vertex_count_;
  std::vector<int> quad_;
  std::vector<double> phi0_, kappa_;
  std::vector<double> cos0_, sin0_;  // cos and sin of the rest angle, from the normals as at run time
  ElementAssembly assembly_;
};

// The signed dihedral angle phi of the hinge (x0, x1, x2, x3) as above, in (-pi, pi].
double hinge_angle(const double* x0, const double* x1, const double* x2, const double* x3);

}  // namespace cmp::shell
