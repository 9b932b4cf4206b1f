#pragma once
// What a shell run measures (thesis Ch. 4 and B.5-B.7), over every vertex of the system (one
// shell in `shellpack shell`): enclosed volume and area, turgor, the gyration tensor and
// asphericity (Eq. 4.6), the force on the walls, contact areas and each term's energy.
#include "shell/shell_system.hpp"

#include <array>
#include <string>
#include <vector>

namespace cmp::shell {

struct Observables {
  double volume = 0;            // signed enclosed volume, summed over the shells [length^3] (0 for an open mesh)
  double area = 0;              // surface area [length^2]
  double turgor = 0;            // Pi of shell 0 [pressure] (0 without a pressure term)
  std::array<double, 3> gyration{};  // eigenvalues lambda_1^2 >= lambda_2^2 >= lambda_3^2 of S [length^2]
  double asphericity = 0;       // b = lambda_1^2 - (lambda_2^2 + lambda_3^2)/2 [length^2]
  double wall_force = 0;        // mean over the walls of the normal force on each [force]
  double wall_contact_area = 0; // area of the faces whose 3 vertices touch a wall [length^2]
  double shell_contact_area = 0;  // area of the faces whose 3 vertices touch another shell [length^2]
  long folded_hinges = 0;       // see folded_hinges()
  double energy = 0;            // total [energy]
  std::vector<double> term_energies;  // in the order of s.terms()
};

// Observables of the system at x.
Observables observe(const ShellSystem& s, const Eigen::VectorXd& x);

// The gyration tensor S_ab = (1/N) sum_i (r_i - r_cm)_a (r_i - r_cm)_b of the points x
// (3 N doubles), its eigenvalues in decreasing order.
std::array<double, 3> gyration_eigenvalues(const Eigen::VectorXd& x);

// The contact area rule of Fig. S2.7: the total area at x of the faces of F whose three
// vertices all have touching[v] != 0 (touching holds one flag per vertex).
double contact_area(const Eigen::VectorXd& x, const mesh::FaceMatrix& F, const std::vector<char>& touching);

// Total area of the faces of F at x.
double surface_area(const Eigen::VectorXd& x, const mesh::FaceMatrix& F);

}  // namespace cmp::shell
