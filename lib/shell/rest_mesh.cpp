#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <string>

namespace cmp::shell {

void check_rest_mesh(const mesh::TriMesh& rest, const char* style) {
  const std::string s = style;
  const Eigen::Index n = rest.V.rows();
  if (!rest.V.allFinite()) throw UsageError(s + ": the rest mesh has a non-finite vertex position");
  for (Eigen::Index f = 0; f < rest.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (rest.F(f, k) < 0 || rest.F(f, k) >= n)
        throw UsageError(s + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(rest.F(f, k)) +
                         " of a mesh with " + std::to_string(n) + " vertices");
    const Eigen::Vector3d a = rest.V.row(rest.F(f, 0)), b = rest.V.row(rest.F(f, 1)), c = rest.V.row(rest.F(f, 2));
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (!(0.5 * (b - a).cross(c - a).norm() > 1e-14 * longest))
      throw UsageError(s + ": rest triangle " + std::to_string(f) + " is degenerate (zero area)");
  }
}

}  // namespace cmp::shell
