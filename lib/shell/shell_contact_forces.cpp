#include "shell/shell_contact_forces.hpp"

#include "shell/hertz_contacts.hpp"

#include "core/errors.hpp"
#include "mesh/dual_areas.hpp"
#include "mesh/face_areas.hpp"
#include "mesh/face_normals.hpp"
#include "neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace cmp::shell {

namespace {

using Key = std::tuple<int, int, int, int, int>;  // m, n, image x y z

Key key_of(int m, int n, const Eigen::Vector3i& k) { return {m, n, k[0], k[1], k[2]}; }

// The search box: the periodic axes as given, the others the vertices' extent padded by the
// cutoff (as VertexContacts does).
neighbours::Box search_box(const mesh::VertexMatrix& V, const neighbours::Box& box, double cutoff) {
  neighbours::Box b;
  b.periodic = box.periodic;
  const Eigen::Vector3d lo = V.colwise().minCoeff().transpose(), hi = V.colwise().maxCoeff().transpose();
  for (int a = 0; a < 3; ++a) {
    if (box.periodic[a]) {
      b.lower[a] = box.lower[a];
      b.lengths[a] = box.lengths[a];
    } else {
      b.lower[a] = lo[a] - cutoff;
      b.lengths[a] = hi[a] - lo[a] + 2 * cutoff;
    }
  }
  if (!b.lower.allFinite() || !b.lengths.allFinite()) throw ComputationError("shell contacts: a vertex position is not finite");
  return b;
}

}  // namespace

std::vector<ShellContact> shell_contacts(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
                                         const std::vector<int>& offsets, const neighbours::Box& box,
                                         const ContactParameters& p) {
  validate(p, "shell contacts");
  const int nv = static_cast<int>(V.rows());
  if (nv == 0 || offsets.size() < 2) return {};
  std::vector<int> shell_of(nv, -1);
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
    for (int i = offsets[k]; i < offsets[k + 1]; ++i) shell_of[i] = static_cast<int>(k);

  const double cutoff = 2.0 * p.vertex_radius, estar = p.vertex_effective_modulus(), rstar = 0.5 * p.vertex_radius;
  neighbours::CellGrid grid(search_box(V, box, cutoff), cutoff);
  grid.build(V);

  // The force on each vertex from each contact: (contact, vertex) -> f.
  std::map<Key, int> index;
  std::vector<ShellContact> found;
  std::map<std::pair<int, int>, Eigen::Vector3d> vertex_force;
  auto add = [&](int i, int m, int n, const Eigen::Vector3i& k, const Eigen::Vector3d& f) {
    auto [it, fresh] = index.emplace(key_of(m, n, k), static_cast<int>(found.size()));
    if (fresh) {
      ShellContact c;
      c.m = m, c.n = n, c.image = k;
      found.push_back(c);
    }
    found[it->second].vertex_pairs += 1;
    auto [vt, vfresh] = vertex_force.emplace(std::make_pair(it->second, i), f);
    if (!vfresh) vt->second += f;
  };
  grid.for_each_pair(V, [&](int i, int j, const Eigen::Vector3d& d, double r2) {
    const int m = shell_of[i], n = shell_of[j];
    if (m == n || m < 0 || n < 0) return;
    const double r = std::sqrt(r2);
    const Eigen::Vector3d f = (hertz_force(cutoff - r, estar, rstar) / r) * d;  // on i, along d = x_i - x_j
    // The image of n seen from m: d = x_i - x_j + k L (minimum image of unwrapped positions)
    // means n's vertices sit at x_j - k L.
    Eigen::Vector3i k = Eigen::Vector3i::Zero();
    for (int a = 0; a < 3; ++a)
      if (box.periodic[a]) k[a] = -static_cast<int>(std::lround((d[a] - (V(i, a) - V(j, a))) / box.lengths[a]));
    add(i, m, n, k, f);
    add(j, n, m, -k, -f);
  });

  // Eq. S4.5 per vertex: the area-weighted mean of |f . n_j| over the faces around i, along f.
  const mesh::VertexMatrix normals = mesh::face_normals(V, F);
  const Eigen::VectorXd areas = mesh::face_areas(V, F), dual = mesh::vertex_dual_areas(V, F);
  std::vector<std::vector<int>> faces_of(nv);
  for (int f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) faces_of[F(f, c)].push_back(f);
  for (const auto& [cv, f] : vertex_force) {
    auto& c = found[cv.first];
    const int i = cv.second;
    c.force += f;
    const double norm = f.norm();
    if (norm == 0 || !(dual[i] > 0)) continue;
    double s = 0;
    for (int j : faces_of[i]) s += areas[j] * std::abs(f.dot(normals.row(j).transpose()));
    c.normal += (s / (3.0 * dual[i]) / norm) * f;
  }
  for (auto& c : found) c.tangential = c.force - c.normal;
  // Sorted by key: map order.
  std::vector<ShellContact> out;
  out.reserve(found.size());
  for (const auto& [k, idx] : index) out.push_back(found[idx]);
  return out;
}

std::vector<int> contacts_per_shell(const std::vector<ShellContact>& contacts, int shells) {
  std::vector<int> z(shells, 0);
  for (const auto& c : contacts)
    if (c.m >= 0 && c.m < shells) ++z[c.m];
  return z;
}

double effective_friction(const std::vector<ShellContact>& contacts) {
  double mu = 0;
  for (const auto& c : contacts) {
    const double n = c.normal.norm();
    if (n > 0) mu = std::max(mu, c.tangential.norm() / n);
  }
  return mu;
}

}  // namespace cmp::shell
