#pragma once
// A constant turgor pressure Pi inside a closed, outward-oriented triangle mesh (thesis B.2.4,
// pressure force II at constant Pi): E = -Pi V, V the signed enclosed volume
//   V = sum over faces (a, b, c) of a . (b x c) / 6
// (the tetrahedra on every face and a common apex; the apex drops out of the total for a
// closed mesh, so the origin serves). The force -dE/dx_a = Pi sum_faces (b x c)/6 points
// outward for Pi > 0: the shell inflates (the minus sign printed in B.50-B.53 would deflate
// it). The signed volume is used, not B.54's absolute value, which has no useful gradient.
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

// The signed volume of x (3 #V doubles) for faces given as 3 corners each (flat).
double signed_volume(std::span<const double> x, const std::vector<int>& corners);

class TurgorPressure final : public EnergyTerm {
 public:
  // Only the faces of `rest` are used. Throws cmp::UsageError for a non-finite Pi, a face
  // index outside the mesh, a mesh that is not a closed, consistently oriented manifold, or one
  // whose rest signed volume is not positive (faces oriented inward).
  TurgorPressure(const mesh::TriMesh& rest, const PressureParameters& p);
  std::string name() const override { return "turgor"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }
  double turgor() const { return turgor_; }

 private:
  double turgor_;
  long vertex_count_;
  std::vector<int> corners_;
};

}  // namespace cmp::shell
