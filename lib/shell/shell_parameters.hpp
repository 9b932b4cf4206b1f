#pragma once
// Typed parameters of the shell styles, checked once when a style is built.
#include <Eigen/Core>

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace cmp::shell {

// An isotropic elastic sheet (stretching and bending styles).
struct MaterialParameters {
  double youngs_modulus = 1.0;  // E [pressure units], > 0
  double poisson_ratio = 1.0 / 3.0;  // nu, in (-1, 0.5]
  double thickness = 1.0;       // t [length], > 0
  // The 2D stretching modulus Y = E t (thesis B.2.1).
  double stretching_modulus() const { return youngs_modulus * thickness; }
  // The bending rigidity kappa = E t^3 / (12 (1 - nu^2)) (thesis B.2.1).
  double bending_rigidity() const {
    return youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  }
};

// Throws cmp::UsageError naming the first bad value: E or t not positive and finite, nu
// outside (-1, 0.5]. `style` prefixes the message ("svk: Poisson ratio nu = 0.7 ...").
void validate(const MaterialParameters& p, const char* style);

// A constant turgor pressure.
struct PressureParameters {
  double turgor = 0.0;  // Pi [pressure units], finite (Pi > 0 inflates)
};

// Throws cmp::UsageError when Pi is not finite.
void validate(const PressureParameters& p, const char* style);

// Fixed external forces on the vertices (a dead load).
struct LoadParameters {
  std::vector<double> forces;  // 3 #V doubles [force units], the force on every vertex; empty: none
};

// A rigid plane x . normal = point . normal; the shells live on the side the unit normal
// points to.
struct Plane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  // Signed distance of p from the plane, positive on the shells' side.
  double distance(const double* p) const {
    return (p[0] - point[0]) * normal[0] + (p[1] - point[1]) * normal[1] + (p[2] - point[2]) * normal[2];
  }
};

// Hertz contacts of the vertices (thesis B.2.5, Eq. B.60): every vertex is a sphere of radius
// R_v. Between vertices of different shells E* = E / (2 (1 - nu^2)), R* = R_v / 2,
// h = 2 R_v - r; against a wall R* = R_v, 1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w,
// h = R_v - (distance to the plane). Energy (8/15) E* sqrt(R*) h^(5/2) per contact, whose
// force (4/3) E* sqrt(R*) h^(3/2) is B.60's, repulsive.
struct ContactParameters {
  double vertex_radius = 0.1;     // R_v [length], > 0 (the thesis takes the wall thickness t)
  // hertz-faces: the contact distance delta [length], > 0, at which a vertex touches another
  // shell's mid-surface (the wall thickness t: each wall's outer face t/2 from its mid-surface).
  double contact_distance = 0.1;
  double youngs_modulus = 1.0;    // E of the vertex spheres [pressure], > 0
  double poisson_ratio = 0.5;     // nu of the vertex spheres, in (-1, 0.5]
  double wall_modulus = std::numeric_limits<double>::infinity();  // E_w, > 0; infinity: rigid
  double wall_poisson_ratio = 0.5;  // nu_w, in (-1, 0.5]
  std::vector<Plane> walls;       // unit normals
  // hertz-vertices: the box [0, L) of a packing, periodic along the flagged axes (minimum
  // image), or none (open space). See VertexContacts::set_box.
  std::optional<Eigen::Vector3d> box;
  std::array<bool, 3> box_periodic{true, true, true};

  double vertex_effective_modulus() const { return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio)); }
  double wall_effective_modulus() const {
    return 1.0 / ((1.0 - poisson_ratio * poisson_ratio) / youngs_modulus +
                  (1.0 - wall_poisson_ratio * wall_poisson_ratio) / wall_modulus);
  }
};

// Throws cmp::UsageError naming the first bad value (R_v, delta, moduli, Poisson ratios, a wall
// normal that is not a finite unit vector or a non-finite wall point).
void validate(const ContactParameters& p, const char* style);

}  // namespace cmp::shell
