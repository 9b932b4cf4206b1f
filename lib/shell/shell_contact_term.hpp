#pragma once
// What a packing run needs of a contact law between the shells of one mesh, whatever the law:
// hertz-vertices (vertex spheres, hertz_contacts.hpp) and hertz-faces (vertices against the
// other shells' triangles, vertex_face_contacts.hpp) both are one. A compression, its virial
// pressure and contact number, and the contact forces of `shellpack analyze` see only this.
#include "shell/energy_term.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

namespace cmp::shell {

class ShellContactTerm : public EnergyTerm {
 public:
  // The box [0, L) the vertices live in, periodic along the flagged axes (minimum image), or
  // none (open space). May change between relaxations (a box being compressed).
  struct BoxSides {
    Eigen::Vector3d lengths;
    std::array<bool, 3> periodic;
  };
  virtual void set_box(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) = 0;
  virtual void clear_box() = 0;
  virtual const std::optional<BoxSides>& box() const = 0;

  // The distance between two shells' mid-surfaces at which they start to touch: 2 R_v for
  // vertex spheres, delta for vertices against faces. Shells placed this far apart start
  // free of contact.
  virtual double contact_reach() const = 0;
  // The shell of every vertex (the mesh's connected components).
  virtual const std::vector<int>& vertex_shells() const = 0;
  // 1 for every vertex in a contact at x.
  virtual std::vector<char> touching(std::span<const double> x) const = 0;

  // One contact: vertex i of one shell pushed by the point q of another shell, q =
  // sum_k weights[k] x_{corners[k]} (a vertex: corners {j, -1, -1}, weights {1, 0, 0}; a
  // triangle: its corners and the barycentric weights of the closest point). d = x_i - q in
  // the minimum image (q taken in x_i's image), r = |d|, overlap > 0, force the repulsive
  // magnitude along d on x_i; the corners take -weights[k] force d/r.
  struct Touch {
    int i;
    std::array<int, 3> corners;
    Eigen::Vector3d weights;
    Eigen::Vector3d d;
    double r, overlap, force;
  };
  // Every contact at x, in a fixed order.
  virtual std::vector<Touch> touches(std::span<const double> x) const = 0;
};

// The point q of a touch in the other shell's own frame (its vertices as stored in x).
inline Eigen::Vector3d touch_point(const ShellContactTerm::Touch& t, std::span<const double> x) {
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (t.corners[k] >= 0) q += t.weights[k] * Eigen::Vector3d(x[3 * t.corners[k]], x[3 * t.corners[k] + 1], x[3 * t.corners[k] + 2]);
  return q;
}

// The periodic image of the other shell, in box vectors, that a touch reaches from x_i's shell:
// d = x_i - q + k L for q in the other shell's own frame means that shell's image sits at its
// stored positions - k L. Zero along the axes that are not periodic.
inline Eigen::Vector3i touch_image(const ShellContactTerm::Touch& t, std::span<const double> x,
                                   const Eigen::Vector3d& lengths, const std::array<bool, 3>& periodic) {
  const Eigen::Vector3d q = touch_point(t, x);
  Eigen::Vector3i k = Eigen::Vector3i::Zero();
  for (int a = 0; a < 3; ++a)
    if (periodic[a]) k[a] = -static_cast<int>(std::lround((t.d[a] - (x[3 * t.i + a] - q[a])) / lengths[a]));
  return k;
}

}  // namespace cmp::shell
