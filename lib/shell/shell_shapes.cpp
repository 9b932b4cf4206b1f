#include "shell/shell_shapes.hpp"

#include "shell/observables.hpp"

#include <cmath>
#include <limits>

namespace cmp::shell {

double reduced_aspect_ratio(const std::array<double, 3>& g) {
  if (!(g[2] > 0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(g[0] / g[2]) - 1.0;
}

std::vector<ShellShape> shell_shapes(const mesh::VertexMatrix& V, const std::vector<int>& offsets) {
  std::vector<ShellShape> out;
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k) {
    const Eigen::Index first = offsets[k], n = offsets[k + 1] - offsets[k];
    ShellShape s;
    if (n > 0) {
      s.centre = V.middleRows(first, n).colwise().mean().transpose();
      const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(V.row(first).data(), 3 * n);
      s.gyration = gyration_eigenvalues(x);
      s.asphericity = s.gyration[0] - 0.5 * (s.gyration[1] + s.gyration[2]);
      s.aspect_deviation = reduced_aspect_ratio(s.gyration);
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace cmp::shell
