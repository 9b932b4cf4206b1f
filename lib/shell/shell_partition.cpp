#include "shell/shell_partition.hpp"

#include <numeric>

namespace cmp::shell {

ShellPartition shell_partition(const mesh::FaceMatrix& F, int vertex_count) {
  std::vector<int> parent(static_cast<std::size_t>(vertex_count));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  const auto join = [&](int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the lowest index
  };
  std::vector<char> used(static_cast<std::size_t>(vertex_count), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    join(F(f, 0), F(f, 1));
    join(F(f, 0), F(f, 2));
    for (int k = 0; k < 3; ++k) used[F(f, k)] = 1;
  }
  ShellPartition p;
  p.vertex_shell.assign(static_cast<std::size_t>(vertex_count), -1);
  std::vector<int> id_of_root(static_cast<std::size_t>(vertex_count), -1);
  for (int v = 0; v < vertex_count; ++v) {
    if (!used[v]) continue;
    const int r = root(v);
    if (id_of_root[r] < 0) id_of_root[r] = p.shell_count++;
    p.vertex_shell[v] = id_of_root[r];
  }
  p.face_shell.resize(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) p.face_shell[f] = p.vertex_shell[F(f, 0)];
  return p;
}

}  // namespace cmp::shell
