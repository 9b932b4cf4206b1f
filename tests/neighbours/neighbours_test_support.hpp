#pragma once
// Brute-force references for the tests of lib/neighbours: every pair by O(N^2), compared with
// what the linked cells find.
#include "core/random.hpp"
#include "mesh/tri_mesh.hpp"
#include "neighbours/box.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace cmp::neighbours::testing {

struct Pair {
  int i, j;             // i < j
  Eigen::Vector3d d;    // x_i - x_j, minimum image
  double r2;
  bool operator<(const Pair& o) const { return std::tie(i, j) < std::tie(o.i, o.j); }
};

// Every pair i < j closer than cutoff, through Box::minimum_image.
inline std::vector<Pair> brute_force_pairs(const mesh::VertexMatrix& X, const Box& box, double cutoff) {
  std::vector<Pair> pairs;
  for (int i = 0; i < X.rows(); ++i)
    for (int j = i + 1; j < X.rows(); ++j) {
      const Eigen::Vector3d d = box.minimum_image((X.row(i) - X.row(j)).transpose());
      if (d.squaredNorm() < cutoff * cutoff) pairs.push_back({i, j, d, d.squaredNorm()});
    }
  return pairs;
}

// A pair as reported by a grid, put in the i < j form of brute_force_pairs.
inline Pair canonical(int i, int j, const Eigen::Vector3d& d, double r2) {
  return i < j ? Pair{i, j, d, r2} : Pair{j, i, -d, r2};
}

// n points uniform in the box, and with probability `outside` shifted by a random whole number
// of box lengths along each periodic axis (unwrapped coordinates) or pushed out of the box by up
// to a length along a non-periodic one.
inline mesh::VertexMatrix random_points(int n, const Box& box, std::uint64_t seed, double outside = 0) {
  Random random(seed);
  mesh::VertexMatrix X(n, 3);
  for (int i = 0; i < n; ++i) {
    const bool out = random.uniform() < outside;
    for (int a = 0; a < 3; ++a) {
      X(i, a) = box.lower[a] + box.lengths[a] * random.uniform();
      if (out) X(i, a) += box.lengths[a] * (box.periodic[a] ? static_cast<double>(random.below(7)) - 3 : random.uniform(-1, 1));
    }
  }
  return X;
}

// n points uniform on the sphere of radius r about the origin.
inline mesh::VertexMatrix random_points_on_sphere(int n, double r, std::uint64_t seed) {
  Random random(seed);
  mesh::VertexMatrix X(n, 3);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d p(random.normal(), random.normal(), random.normal());
    X.row(i) = r * p.normalized();
  }
  return X;
}

}  // namespace cmp::neighbours::testing
