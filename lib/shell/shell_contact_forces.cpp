#include "shell/shell_contact_forces.hpp"

#include "shell/hertz_contacts.hpp"
#include "shell/shell_contact_term.hpp"
#include "shell/styles.hpp"

#include "core/errors.hpp"
#include "mesh/dual_areas.hpp"
#include "mesh/face_areas.hpp"
#include "mesh/face_normals.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace cmp::shell {

namespace {

using Key = std::tuple<int, int, int, int, int>;  // m, n, image x y z

Key key_of(int m, int n, const Eigen::Vector3i& k) { return {m, n, k[0], k[1], k[2]}; }

}  // namespace

std::vector<ShellContact> shell_contacts(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
                                         const std::vector<int>& offsets, const neighbours::Box& box,
                                         const ContactParameters& p, const std::string& style) {
  validate(p, "shell contacts");
  const int nv = static_cast<int>(V.rows());
  if (nv == 0 || offsets.size() < 2) return {};
  std::vector<int> shell_of(nv, -1);
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
    for (int i = offsets[k]; i < offsets[k + 1]; ++i) shell_of[i] = static_cast<int>(k);

  // The contact law as the packing run used it, in the packing's box.
  ContactParameters q = p;
  q.box = box.lengths;
  q.box_periodic = box.periodic;
  const auto term = contact_style(style).make(mesh::TriMesh{V, F}, q);
  const auto* law = dynamic_cast<const ShellContactTerm*>(term.get());
  if (!law) throw UsageError("shell contacts: '" + style + "' is not a contact style between shells");
  const std::span<const double> x(V.data(), static_cast<std::size_t>(V.size()));

  // The force on each vertex from each contact: (contact, vertex) -> f.
  std::map<Key, int> index;
  std::vector<ShellContact> found;
  std::map<std::pair<int, int>, Eigen::Vector3d> vertex_force;
  auto add = [&](int i, int m, int n, const Eigen::Vector3i& k, const Eigen::Vector3d& f, bool pushed) {
    auto [it, fresh] = index.emplace(key_of(m, n, k), static_cast<int>(found.size()));
    if (fresh) {
      ShellContact c;
      c.m = m, c.n = n, c.image = k;
      found.push_back(c);
    }
    if (pushed) found[it->second].vertex_pairs += 1;
    auto [vt, vfresh] = vertex_force.emplace(std::make_pair(it->second, i), f);
    if (!vfresh) vt->second += f;
  };
  for (const auto& t : law->touches(x)) {
    if (!(t.r > 0)) continue;
    const int m = shell_of[t.i], n = shell_of[t.corners[0]];
    if (m == n || m < 0 || n < 0) continue;
    const Eigen::Vector3d f = (t.force / t.r) * t.d;  // on i, along d = x_i - q
    const Eigen::Vector3i k = touch_image(t, x, box.lengths, box.periodic);  // n's image seen from m
    add(t.i, m, n, k, f, true);
    bool counted = false;  // the touch counts once in each direction
    for (int c = 0; c < 3; ++c)
      if (t.corners[c] >= 0 && t.weights[c] > 0) {
        add(t.corners[c], n, m, -k, -t.weights[c] * f, !counted);
        counted = true;
      }
  }

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
