#pragma once
// The shape of each shell of a packing (thesis Ch. 4, Eq. 4.6 and Fig. 4.4): its centre (the
// mean of its vertices), the eigenvalues of its gyration tensor, the asphericity
// b = l1^2 - (l2^2 + l3^2)/2 and the reduced aspect ratio delta_eps = l1/l3 - 1.
#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cmp::shell {

struct ShellShape {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // vertex mean [length]; as unwrapped, not wrapped into the box
  std::array<double, 3> gyration{};  // lambda_1^2 >= lambda_2^2 >= lambda_3^2 of S_ab [length^2]
  double asphericity = 0;            // b [length^2]; 0 for a sphere
  double aspect_deviation = 0;       // delta_eps = lambda_1/lambda_3 - 1 [1]; 0 for a sphere (inf when lambda_3 = 0)
};

// One shape per shell: shell k owns rows [offsets[k], offsets[k+1]) of V, each shell unwrapped
// into one periodic image (packing::unwrap_shells) so that its vertex cloud is whole. The
// gyration tensor is over the vertices (Eq. 4.6), not the surface.
std::vector<ShellShape> shell_shapes(const mesh::VertexMatrix& V, const std::vector<int>& offsets);

// delta_eps = sqrt(g[0] / g[2]) - 1 of gyration eigenvalues in decreasing order.
double reduced_aspect_ratio(const std::array<double, 3>& gyration);

}  // namespace cmp::shell
