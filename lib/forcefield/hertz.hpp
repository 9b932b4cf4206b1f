#pragma once
// The Hertz contact law (thesis Eq. B.60 of B.2.5, and 5.5.1), the one every contact style
// uses: soft spheres (spheres/hertz_spheres.hpp), shell vertices and faces and walls
// (shell/hertz_contacts.hpp, shell/vertex_face_contacts.hpp), budding-cell lobes
// (cells2d/contact_law.hpp, in units of k):
//   F = (4/3) E* sqrt(R*) h^(3/2),   U = (8/15) E* sqrt(R*) h^(5/2),
// h = R_i + R_j - |x_i - x_j| the overlap, 1/R* = 1/R_i + 1/R_j, and for two spheres of one
// material 1/E* = 2 (1 - nu^2) / E. The force pushes the spheres apart (the printed minus sign
// of B.60 and 5.5.1, with R along R_i - R_j, would pull them together).
#include <cmath>

namespace cmp {

struct HertzMaterial {
  double youngs_modulus = 1.0;  // E (thesis Ch. 5: 1)
  double poisson_ratio = 0.5;   // nu (thesis Ch. 5: 0.5)

  // E* = E / (2 (1 - nu^2)): 2/3 for the thesis's E = 1, nu = 0.5.
  double effective_modulus() const { return youngs_modulus / (2 * (1 - poisson_ratio * poisson_ratio)); }
  // Throws cmp::UsageError unless E > 0 and -1 < nu < 1.
  void validate() const;
};

// R* = R_i R_j / (R_i + R_j).
inline double effective_radius(double r_i, double r_j) { return r_i * r_j / (r_i + r_j); }

// (4/3) E* sqrt(R*): the force is this times h^(3/2).
inline double hertz_prefactor(double effective_modulus, double effective_radius) {
  return 4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius);
}
inline double hertz_prefactor(const HertzMaterial& m, double r_i, double r_j) {
  return hertz_prefactor(m.effective_modulus(), effective_radius(r_i, r_j));
}

// Magnitude of the repulsive force at overlap h (0 for h <= 0).
inline double hertz_force(double prefactor, double h) { return h > 0 ? prefactor * h * std::sqrt(h) : 0.0; }
// Elastic energy at overlap h (0 for h <= 0): (2/5) F h.
inline double hertz_energy(double prefactor, double h) { return h > 0 ? 0.4 * prefactor * h * h * std::sqrt(h) : 0.0; }

}  // namespace cmp
