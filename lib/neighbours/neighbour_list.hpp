#pragma once
// A Verlet neighbour list: for every particle, all particles within cutoff + skin at the last
// build, in compressed-row form. As long as no particle has moved more than skin/2 since, it
// holds every pair now within the cutoff, so a force loop reads it instead of searching:
//
//   NeighbourList list(box, cutoff, skin);
//   list.build(X);
//   ... each step:
//   if (list.needs_rebuild(X)) list.build(X);
//   #pragma omp parallel for
//   for (int i = 0; i < n; ++i)
//     for (int j : list.neighbours_of(i)) {
//       const Eigen::Vector3d d = list.minimum_image(X.row(i) - X.row(j));  // x_i - x_j
//       if (d.squaredNorm() < cutoff * cutoff) force.row(i) += ...;        // writes row i only
//     }
//
// The list is full (j in row i and i in row j), so each thread writes only its own particles.
#include "mesh/tri_mesh.hpp"
#include "neighbours/box.hpp"
#include "neighbours/cell_grid.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <vector>

namespace cmp::neighbours {

class NeighbourList {
 public:
  // Throws cmp::UsageError unless cutoff > 0, skin >= 0 and cutoff + skin <= L/2 along every
  // periodic axis (see CellGrid).
  NeighbourList(const Box& box, double cutoff, double skin);

  // Lists, for every row i of X (#N by 3), every j != i with |x_i - x_j| < cutoff + skin
  // (minimum image), rows sorted ascending. O(N) through a CellGrid of cutoff + skin, in
  // parallel over cells with OpenMP; the result does not depend on the number of threads.
  // Remembers X for needs_rebuild. Throws cmp::ComputationError on a non-finite coordinate.
  void build(const mesh::VertexMatrix& X);

  // True when X has a different number of rows than at the build, or when some particle has
  // moved more than skin/2 (minimum image, so wrapping a particle into the box is no move)
  // since the build. Until then every pair within the cutoff is in the list. O(N).
  bool needs_rebuild(const mesh::VertexMatrix& X) const;

  // Rebuilds if needs_rebuild(X); returns whether it did.
  bool update(const mesh::VertexMatrix& X);

  // Row i: the neighbours of particle i, ascending.
  std::span<const int> neighbours_of(int i) const {
    return {neighbours_.data() + offsets_[static_cast<std::size_t>(i)],
            neighbours_.data() + offsets_[static_cast<std::size_t>(i) + 1]};
  }
  // The compressed rows: row i is neighbours()[offsets()[i] .. offsets()[i + 1]).
  const std::vector<std::size_t>& offsets() const { return offsets_; }
  const std::vector<int>& neighbours() const { return neighbours_; }
  std::size_t pair_count() const { return neighbours_.size() / 2; }
  int particle_count() const { return static_cast<int>(offsets_.size()) - 1; }

  // x_i - x_j reduced to the minimum image, as the list measured it.
  Eigen::Vector3d minimum_image(const Eigen::Vector3d& d) const { return grid_.minimum_image(d); }

  double cutoff() const { return cutoff_; }
  double skin() const { return skin_; }
  double radius() const { return cutoff_ + skin_; }  // the list's own cutoff
  const Box& box() const { return grid_.box(); }
  const CellGrid& grid() const { return grid_; }
  long builds() const { return builds_; }

 private:
  struct ThreadRows {                 // what one thread found, before the rows are placed
    std::vector<int> neighbours;      // its rows one after the other
    std::vector<int> particles;       // which particle each row belongs to
    std::vector<std::size_t> starts;  // where each row begins in `neighbours`
    // the candidates of the current cell (its stencil's members), structure of arrays
    std::vector<double> x, y, z, r2;
    std::vector<int> ids;
  };

  double cutoff_, skin_;
  CellGrid grid_;
  long builds_ = 0;
  mesh::VertexMatrix reference_;      // positions at the last build
  std::vector<std::size_t> offsets_{0};
  std::vector<int> neighbours_;
  std::vector<ThreadRows> scratch_;   // kept between builds to reuse the memory
  std::vector<double> sorted_x_, sorted_y_, sorted_z_;  // positions in cell order
};

}  // namespace cmp::neighbours
