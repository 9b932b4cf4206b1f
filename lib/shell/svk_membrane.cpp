#include "shell/svk_membrane.hpp"

#include "shell/rest_mesh.hpp"

#include <cmath>

namespace cmp::shell {

SvkMembrane::SvkMembrane(const mesh::TriMesh& rest, const MaterialParameters& p) : vertex_count_(rest.V.rows()) {
  validate(p, "svk");
  check_rest_mesh(rest, "svk");
  const Eigen::Index nf = rest.F.rows();
  corners_.resize(3 * nf);
  rest_l2_.resize(3 * nf);
  k_.resize(3 * nf);
  c_.resize(3 * nf);
  const double Y = p.stretching_modulus(), nu = p.poisson_ratio;
  for (Eigen::Index f = 0; f < nf; ++f) {
    Eigen::Vector3d P[3];
    for (int i = 0; i < 3; ++i) {
      corners_[3 * f + i] = rest.F(f, i);
      P[i] = rest.V.row(rest.F(f, i)).transpose();
    }
    const double A = 0.5 * (P[1] - P[0]).cross(P[2] - P[0]).norm();
    double cot[3];
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d u = P[(i + 1) % 3] - P[i], v = P[(i + 2) % 3] - P[i];
      cot[i] = u.dot(v) / u.cross(v).norm();  // cot of the rest angle at corner i
      rest_l2_[3 * f + i] = (P[(i + 2) % 3] - P[(i + 1) % 3]).squaredNorm();
    }
    const double scale = Y / (16.0 * (1.0 - nu * nu) * A);
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      k_[3 * f + i] = scale * (2.0 * cot[i] * cot[i] + 1.0 - nu);
      c_[3 * f + i] = scale * (2.0 * cot[a] * cot[b] + nu - 1.0);
    }
  }
}

double SvkMembrane::energy(std::span<const double> x) const {
  check_sizes(x);
  const double* X = x.data();
  const std::size_t nf = corners_.size() / 3;
  double sum = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const int* q = &corners_[3 * f];
    double d[3];
    for (int i = 0; i < 3; ++i) {
      const double* u = X + 3 * q[(i + 1) % 3];
      const double* v = X + 3 * q[(i + 2) % 3];
      const double dx = v[0] - u[0], dy = v[1] - u[1], dz = v[2] - u[2];
      d[i] = dx * dx + dy * dy + dz * dz - rest_l2_[3 * f + i];
    }
    const double* k = &k_[3 * f];
    const double* c = &c_[3 * f];
    sum += 0.25 * (k[0] * d[0] * d[0] + k[1] * d[1] * d[1] + k[2] * d[2] * d[2]) +
           0.5 * (c[0] * d[1] * d[2] + c[1] * d[2] * d[0] + c[2] * d[0] * d[1]);
  }
  return sum;
}

void SvkMembrane::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const double* X = x.data();
  double* G = g.data();
  const std::size_t nf = corners_.size() / 3;
  for (std::size_t f = 0; f < nf; ++f) {
    const int* q = &corners_[3 * f];
    double e[3][3], d[3];
    for (int i = 0; i < 3; ++i) {
      const double* u = X + 3 * q[(i + 1) % 3];
      const double* v = X + 3 * q[(i + 2) % 3];
      for (int r = 0; r < 3; ++r) e[i][r] = v[r] - u[r];
      d[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2] - rest_l2_[3 * f + i];
    }
    const double* k = &k_[3 * f];
    const double* c = &c_[3 * f];
    // dE/d(l_i^2), times 2 for d(l_i^2)/d(end) = 2 e_i.
    const double w[3] = {k[0] * d[0] + c[2] * d[1] + c[1] * d[2],  //
                         k[1] * d[1] + c[2] * d[0] + c[0] * d[2],  //
                         k[2] * d[2] + c[1] * d[0] + c[0] * d[1]};
    for (int i = 0; i < 3; ++i) {
      double* gu = G + 3 * q[(i + 1) % 3];
      double* gv = G + 3 * q[(i + 2) % 3];
      for (int r = 0; r < 3; ++r) {
        gv[r] += w[i] * e[i][r];
        gu[r] -= w[i] * e[i][r];
      }
    }
  }
}

}  // namespace cmp::shell
