#include "shell/shell_system.hpp"

#include "shell/dihedral_hinges.hpp"
#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"
#include "mesh/edge_topology.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace cmp::shell {

ShellSystem::ShellSystem(mesh::TriMesh rest) : rest_(std::move(rest)) {
  check_rest_mesh(rest_, "shell");
  const int n = static_cast<int>(rest_.V.rows());
  shells_ = shell_partition(rest_.F, n);
  for (int v = 0; v < n; ++v)
    if (shells_.vertex_shell[v] < 0)
      throw UsageError("shell: vertex " + std::to_string(v) + " belongs to no face (remove unused vertices)");
  fixed_.assign(static_cast<std::size_t>(n), 0);
  x = Eigen::Map<const Eigen::VectorXd>(rest_.V.data(), 3 * n);
  // Hinges for the fold check: interior edges whose two faces run them opposite ways.
  const auto topo = mesh::edge_topology(rest_.F);
  const auto third = [&](int f, int i, int j) {
    for (int c = 0; c < 3; ++c)
      if (rest_.F(f, c) != i && rest_.F(f, c) != j) return rest_.F(f, c);
    return -1;
  };
  const double* X = rest_.V.data();
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    if (topo.edge_face_counts[e] != 2) continue;
    int i = topo.edges(e, 0), j = topo.edges(e, 1), f0 = topo.edge_faces(e, 0), f1 = topo.edge_faces(e, 1);
    if (!mesh::face_has_side(rest_.F, f0, i, j)) std::swap(f0, f1);
    if (!mesh::face_has_side(rest_.F, f0, i, j)) std::swap(i, j);
    if (!mesh::face_has_side(rest_.F, f0, i, j) || !mesh::face_has_side(rest_.F, f1, j, i)) continue;
    const int k = third(f0, i, j), l = third(f1, i, j);
    hinge_quads_.insert(hinge_quads_.end(), {i, j, k, l});
    hinge_rest_.push_back(hinge_angle(X + 3 * i, X + 3 * j, X + 3 * k, X + 3 * l));
  }
}

void ShellSystem::add(std::unique_ptr<EnergyTerm> term) {
  if (!term || term->vertex_count() != vertex_count())
    throw std::invalid_argument("shell: a term built for another mesh");
  if (!pressure_) pressure_ = dynamic_cast<TurgorPressure*>(term.get());
  if (!walls_) walls_ = dynamic_cast<WallContacts*>(term.get());
  if (!contacts_) contacts_ = dynamic_cast<ShellContactTerm*>(term.get());
  terms_.push_back(std::move(term));
}

void ShellSystem::fix(const std::vector<int>& vertices) {
  for (int v : vertices) {
    if (v < 0 || v >= vertex_count()) throw std::invalid_argument("shell: fixed vertex out of range");
    fixed_[v] = 1;
  }
}

double ShellSystem::energy(const Eigen::VectorXd& y) const {
  double e = 0;
  for (const auto& t : terms_) e += t->energy(span_of(y));
  return e;
}

void ShellSystem::forces(const Eigen::VectorXd& y, Eigen::VectorXd& f) const { forces_without(nullptr, y, f); }

void ShellSystem::forces_without(const EnergyTerm* left_out, const Eigen::VectorXd& y, Eigen::VectorXd& f) const {
  // The terms add their gradients into f itself, negated once at the end (no second vector).
  f.setZero(y.size());
  for (const auto& t : terms_)
    if (t.get() != left_out) t->add_gradient(span_of(y), span_of(f));
  f = -f;
  for (long v = 0; v < vertex_count(); ++v)
    if (fixed_[v]) f.segment<3>(3 * v).setZero();
}

std::vector<double> ShellSystem::term_energies(const Eigen::VectorXd& y) const {
  std::vector<double> e;
  for (const auto& t : terms_) e.push_back(t->energy(span_of(y)));
  return e;
}

long folded_hinges(const ShellSystem& s, const Eigen::VectorXd& y) {
  const double* X = y.data();
  const auto& q = s.hinges();
  const auto& rest = s.rest_hinge_angles();
  long folded = 0;
  for (std::size_t h = 0; h < rest.size(); ++h) {
    const double phi = hinge_angle(X + 3 * q[4 * h], X + 3 * q[4 * h + 1], X + 3 * q[4 * h + 2], X + 3 * q[4 * h + 3]);
    double d = std::abs(phi - rest[h]);
    d = std::min(d, 2 * std::numbers::pi - d);
    if (!(d <= 2.0 * std::numbers::pi / 3.0)) ++folded;
  }
  return folded;
}

}  // namespace cmp::shell
