#pragma once
// Hertz contacts of shells (thesis B.2.5-B.2.6, Eq. B.60; parameters in shell_parameters.hpp):
//   VertexContacts  vertex spheres of different shells (the mesh's connected components)
//                   repel; vertices of one shell never interact with each other (the thesis's
//                   "belonging to different shells"). Pairs come from linked cells
//                   (lib/neighbours) rebuilt at every call over the vertices' bounding box, or,
//                   once set_box() gave a box, over that box with the minimum image along its
//                   periodic axes (a packing in a periodic box; a non-periodic axis keeps the
//                   vertices' extent, for rigid walls at 0 and L); in a box the pairs come
//                   from a Verlet list (skin R_v / 2) rebuilt when a vertex has moved a
//                   quarter of R_v or the box changed. The pair loop runs on one thread in a
//                   fixed order: the same bits for any thread count.
//   WallContacts    every vertex sphere against rigid planes (walls that may move between
//                   relaxations: set_walls).
#include "shell/energy_term.hpp"
#include "shell/shell_contact_term.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"
#include "forcefield/hertz.hpp"
#include "neighbours/box.hpp"
#include "neighbours/cell_grid.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace cmp::shell {

class VertexContacts final : public ShellContactTerm {
 public:
  // Throws cmp::UsageError for bad parameters or a face index outside the mesh.
  VertexContacts(const mesh::TriMesh& rest, const ContactParameters& p);
  std::string name() const override { return "hertz-vertices"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return static_cast<long>(shell_of_.size()); }
  // 1 for every vertex overlapping a vertex of another shell at x.
  std::vector<char> touching(std::span<const double> x) const override;

  // Throws cmp::UsageError for a side that is not positive and finite or a periodic side
  // shorter than 5 R_v (twice the Verlet list's reach).
  void set_box(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) override;
  void clear_box() override {
    box_.reset();
    list_valid_ = false;
  }
  const std::optional<BoxSides>& box() const override { return box_; }

  // Every overlapping pair of vertices of different shells at x, in the fixed order of the
  // pair loop: vertex i pushed by vertex j (corners {j, -1, -1}), d = x_i - x_j (minimum
  // image), the overlap h = 2 R_v - r.
  std::vector<Touch> touches(std::span<const double> x) const override;
  const std::vector<int>& vertex_shells() const override { return shell_of_; }
  double contact_reach() const override { return 2.0 * radius_; }
  double vertex_radius() const { return radius_; }

 private:
  static constexpr double kSkin = 0.5;  // Verlet skin [R_v]
  template <class Fn>
  void for_each_contact(std::span<const double> x, Fn&& f) const;
  void build_pair_list(std::span<const double> x) const;
  bool pair_list_holds(std::span<const double> x) const;
  std::vector<int> shell_of_;
  double radius_, estar_;
  std::optional<BoxSides> box_;
  mutable mesh::VertexMatrix scratch_;
  mutable std::vector<std::pair<int, int>> pairs_;
  mutable std::vector<double> reference_;
  mutable bool list_valid_ = false;
};

class WallContacts final : public EnergyTerm {
 public:
  // Throws cmp::UsageError for bad parameters.
  WallContacts(const mesh::TriMesh& rest, const ContactParameters& p);
  std::string name() const override { return "hertz-walls"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }
  const std::vector<Plane>& walls() const { return walls_; }
  void set_walls(std::vector<Plane> walls);
  // The total normal force the vertices exert on each wall at x (>= 0; along -normal).
  std::vector<double> wall_forces(std::span<const double> x) const;
  // 1 for every vertex overlapping a wall at x.
  std::vector<char> touching(std::span<const double> x) const;

 private:
  long vertex_count_;
  double radius_, estar_;
  std::vector<Plane> walls_;
};

// Throws cmp::UsageError naming `style` if a face of `rest` refers to a vertex outside it.
void check_face_indices(const mesh::TriMesh& rest, const char* style);

// The cell-grid box of contacts cut off at `cutoff` among the vertices X: their bounding box
// grown by the cutoff, with the periodic axes of `sides` (if any) replaced by [0, L) and
// flagged periodic. Throws cmp::ComputationError naming `style` on a non-finite position.
neighbours::Box contact_box(const mesh::VertexMatrix& X, double cutoff,
                            const std::optional<ShellContactTerm::BoxSides>& sides, const char* style);

// The cell grid of those contacts, built on X: cells one cutoff wide in open space; in a box,
// about cbrt(#X) cells per axis at most (vertices lie on surfaces: finer grids are mostly
// empty cells).
neighbours::CellGrid contact_grid(const mesh::VertexMatrix& X, double cutoff,
                                  const std::optional<ShellContactTerm::BoxSides>& sides, const char* style);

}  // namespace cmp::shell
