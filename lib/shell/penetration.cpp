#include "shell/penetration.hpp"

#include "mesh/inside_query.hpp"
#include "neighbours/box.hpp"

#include <algorithm>

namespace cmp::shell {

std::vector<Penetration> penetrations(const Eigen::VectorXd& x, const mesh::FaceMatrix& F, const ShellPartition& shells,
                                      const std::optional<Eigen::Vector3d>& box, std::array<bool, 3> periodic) {
  const int k = shells.shell_count;
  const long n = static_cast<long>(shells.vertex_shell.size());
  // Faces of each shell as one list (faces need not be contiguous by shell).
  std::vector<std::vector<int>> faces(static_cast<std::size_t>(k));
  for (Eigen::Index f = 0; f < F.rows(); ++f) faces[shells.face_shell[f]].push_back(static_cast<int>(f));
  std::vector<Eigen::Vector3d> centre(k, Eigen::Vector3d::Zero());
  std::vector<double> reach(k, 0.0), count(k, 0.0);
  for (long v = 0; v < n; ++v) {
    centre[shells.vertex_shell[v]] += x.segment<3>(3 * v);
    count[shells.vertex_shell[v]] += 1;
  }
  for (int s = 0; s < k; ++s) centre[s] /= std::max(count[s], 1.0);
  for (long v = 0; v < n; ++v) {
    const int s = shells.vertex_shell[v];
    reach[s] = std::max(reach[s], (x.segment<3>(3 * v) - centre[s]).norm());
  }
  std::vector<std::vector<int>> vertices(static_cast<std::size_t>(k));
  for (long v = 0; v < n; ++v) vertices[shells.vertex_shell[v]].push_back(static_cast<int>(v));
  // A separation reduced to its minimum image (unchanged without a box).
  std::optional<neighbours::Box> images;
  if (box) images = neighbours::Box{Eigen::Vector3d::Zero(), *box, periodic};
  const auto nearest_image = [&](const Eigen::Vector3d& d) -> Eigen::Vector3d {
    return images ? images->minimum_image(d) : d;
  };
  std::vector<std::vector<Penetration>> found(static_cast<std::size_t>(k));
#pragma omp parallel for schedule(dynamic, 1)
  for (int s = 0; s < k; ++s) {
    mesh::FaceMatrix Fs(static_cast<Eigen::Index>(faces[s].size()), 3);
    for (std::size_t f = 0; f < faces[s].size(); ++f) Fs.row(static_cast<Eigen::Index>(f)) = F.row(faces[s][f]);
    const mesh::InsideQuery inside(x.data(), Fs, 0, Fs.rows());
    for (int t = 0; t < k; ++t) {
      // Only shells whose bounding spheres meet s's can reach into it.
      if (t == s || nearest_image(centre[t] - centre[s]).norm() > reach[s] + reach[t]) continue;
      for (int v : vertices[t]) {
        const Eigen::Vector3d d = nearest_image(x.segment<3>(3 * v) - centre[s]);
        if (d.norm() > reach[s]) continue;
        if (inside.inside(centre[s] + d)) found[s].push_back({v, t, s});
      }
    }
    std::sort(found[s].begin(), found[s].end(), [](const Penetration& a, const Penetration& b) { return a.vertex < b.vertex; });
  }
  std::vector<Penetration> all;
  for (const auto& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

}  // namespace cmp::shell
