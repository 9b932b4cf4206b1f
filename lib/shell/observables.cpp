#include "shell/observables.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace cmp::shell {

namespace {
double face_area(const Eigen::VectorXd& x, const mesh::FaceMatrix& F, Eigen::Index f) {
  const Eigen::Vector3d a = x.segment<3>(3 * F(f, 0)), b = x.segment<3>(3 * F(f, 1)), c = x.segment<3>(3 * F(f, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace

double contact_area(const Eigen::VectorXd& x, const mesh::FaceMatrix& F, const std::vector<char>& touching) {
  double sum = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (touching[F(f, 0)] && touching[F(f, 1)] && touching[F(f, 2)]) sum += face_area(x, F, f);
  return sum;
}

double surface_area(const Eigen::VectorXd& x, const mesh::FaceMatrix& F) {
  double sum = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) sum += face_area(x, F, f);
  return sum;
}

std::array<double, 3> gyration_eigenvalues(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size() / 3;
  if (n == 0) return {0, 0, 0};
  Eigen::Vector3d cm = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) cm += x.segment<3>(3 * i);
  cm /= static_cast<double>(n);
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = x.segment<3>(3 * i) - cm;
    S += d * d.transpose();
  }
  S /= static_cast<double>(n);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S, Eigen::EigenvaluesOnly);
  const auto& l = es.eigenvalues();  // ascending
  return {l[2], l[1], l[0]};
}

Observables observe(const ShellSystem& s, const Eigen::VectorXd& x) {
  Observables o;
  const auto& F = s.rest().F;
  if (const auto* p = s.pressure()) {
    for (double v : p->volumes(span_of(x))) o.volume += v;
    o.turgor = p->turgor();
  }
  o.area = surface_area(x, F);
  o.gyration = gyration_eigenvalues(x);
  o.asphericity = o.gyration[0] - 0.5 * (o.gyration[1] + o.gyration[2]);
  if (const auto* w = s.walls(); w && !w->walls().empty()) {
    const auto forces = w->wall_forces(span_of(x));
    for (double f : forces) o.wall_force += f;
    o.wall_force /= static_cast<double>(forces.size());
    o.wall_contact_area = contact_area(x, F, w->touching(span_of(x)));
  }
  if (const auto* c = s.contacts()) o.shell_contact_area = contact_area(x, F, c->touching(span_of(x)));
  o.folded_hinges = folded_hinges(s, x);
  o.term_energies = s.term_energies(x);
  for (double e : o.term_energies) o.energy += e;
  return o;
}

}  // namespace cmp::shell
