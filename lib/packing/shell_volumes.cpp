#include "packing/shell_volumes.hpp"

#include "mesh/enclosed_volume.hpp"

#include <algorithm>

namespace cmp::packing {

std::vector<double> shell_volumes(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets) {
  const int K = static_cast<int>(offsets.size()) - 1;
  if (K <= 0) return {};
  std::vector<std::vector<int>> faces(K);
  for (int f = 0; f < F.rows(); ++f) {
    const int k = static_cast<int>(std::upper_bound(offsets.begin(), offsets.end(), F(f, 0)) - offsets.begin()) - 1;
    faces[std::clamp(k, 0, K - 1)].push_back(f);
  }
  std::vector<double> volumes(K, 0.0);
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < K; ++k) {
    mesh::FaceMatrix Fk(static_cast<long>(faces[k].size()), 3);
    for (std::size_t i = 0; i < faces[k].size(); ++i) Fk.row(static_cast<long>(i)) = F.row(faces[k][i]);
    volumes[k] = mesh::enclosed_volume(V, Fk);
  }
  return volumes;
}

}  // namespace cmp::packing
