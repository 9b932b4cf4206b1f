#pragma once
// Turgor pressure inside closed, outward-oriented shells (thesis B.2.4, pressure force II):
// E = -sum_s Pi_s V_s over the shells s of the mesh (its connected components, see
// shell_partition.hpp), V_s the signed volume enclosed by shell s,
//   V = sum over its faces (a, b, c) of a . (b x c) / 6
// (the tetrahedra on every face and a common apex; the apex drops out of the total for a
// closed mesh, so the origin serves). The force -dE/dx_a = Pi sum_faces (b x c)/6 points
// outward for Pi > 0: the shell inflates (the minus sign printed in B.50-B.53 would deflate
// it). The signed volume is used, not B.54's absolute value, which has no useful gradient.
//
// Two controls, two registered styles with the same energy:
//   "turgor": Pi fixed (the load of the B.5 and B.7 benchmarks);
//   "volume": a constant volume, an incompressible fill (5.2.1, B.6). During one relaxation
//     Pi is fixed; between relaxations the driver (relax.hpp) moves it by a volume rule
//     (volume_rule.hpp) until every |V_s - V0_s| <= 0.1 % V0_s. The targets
//     V0_s default to the rest volumes; a driver that inflates first sets them to the
//     inflated ones. A shell at Pi = 0 stays at 0 under this rule (as in the thesis, which
//     starts it from the inflated state).
// The gradient is a loop over the vertices, each summing its faces in face order, on all
// threads (the same bits for any thread count); volumes and the energy are summed face by face
// in order.
#include "shell/energy_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace cmp::shell {

// The signed volume of x (3 #V doubles) for faces given as 3 corners each (flat).
double signed_volume(std::span<const double> x, const std::vector<int>& corners);

enum class PressureControl { ConstantTurgor, ConstantVolume };

class TurgorPressure final : public EnergyTerm {
 public:
  // Only the faces of `rest` are used; every shell starts at Pi = p.turgor. Throws
  // cmp::UsageError for a non-finite Pi, a face index outside the mesh, a mesh that is not a
  // closed, consistently oriented manifold, or a shell whose rest signed volume is not
  // positive (faces oriented inward).
  TurgorPressure(const mesh::TriMesh& rest, const PressureParameters& p,
                 PressureControl control = PressureControl::ConstantTurgor);
  std::string name() const override { return control_ == PressureControl::ConstantTurgor ? "turgor" : "volume"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }

  PressureControl control() const { return control_; }
  int shell_count() const { return static_cast<int>(turgor_.size()); }
  // Pi of shell 0 (the one shell of a single-cell run).
  double turgor() const { return turgor_.front(); }
  const std::vector<double>& turgors() const { return turgor_; }
  void set_turgor(double pi);  // every shell
  void set_turgors(const std::vector<double>& pi);
  // The signed volume of every shell at x.
  std::vector<double> volumes(std::span<const double> x) const;
  const std::vector<double>& target_volumes() const { return target_; }
  void set_target_volumes(const std::vector<double>& v0);
  // The largest relative volume error max_s |V_s - V0_s| / V0_s at x.
  double volume_error(std::span<const double> x) const;
  // n = dV_s/dx at x for every vertex (s its shell): the direction the turgor pushes along,
  // and the one a constant-volume constraint acts along (volume_constraint.hpp). n is overwritten.
  void volume_gradient(std::span<const double> x, std::span<double> n) const;
  // The shell of every vertex.
  const std::vector<int>& vertex_shells() const { return vertex_shell_; }

 private:
  void build_rings(const std::vector<int>& face_shell);

  static constexpr long kVertexChunk = 512;
  PressureControl control_;
  long vertex_count_;
  std::vector<int> corners_, face_shell_;
  std::vector<int> shell_face_start_, shell_faces_;  // each shell's faces, ascending (CSR)
  // Vertex v's faces are ring_ pairs first_[v] .. first_[v + 1] (the other two corners, in
  // cyclic order), in face order; its shell is vertex_shell_[v].
  std::vector<int> first_, ring_, vertex_shell_;
  int vertex_chunks_ = 1;
  std::vector<double> turgor_, target_;
  mutable std::vector<double> scale_;  // -Pi/6 per shell, for the gradient pass
};

}  // namespace cmp::shell
