#include "shell/turgor_pressure.hpp"

#include "core/errors.hpp"
#include "mesh/manifold.hpp"

#include <string>

namespace cmp::shell {

double signed_volume(std::span<const double> x, const std::vector<int>& corners) {
  const double* X = x.data();
  const std::size_t nf = corners.size() / 3;
  double sum = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const double* a = X + 3 * corners[3 * f];
    const double* b = X + 3 * corners[3 * f + 1];
    const double* c = X + 3 * corners[3 * f + 2];
    sum += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return sum / 6.0;
}

TurgorPressure::TurgorPressure(const mesh::TriMesh& rest, const PressureParameters& p)
    : turgor_(p.turgor), vertex_count_(rest.V.rows()) {
  validate(p, "turgor");
  corners_.resize(3 * rest.F.rows());
  for (Eigen::Index f = 0; f < rest.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = rest.F(f, k);
      if (v < 0 || v >= rest.V.rows())
        throw UsageError("turgor: face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                         " of a mesh with " + std::to_string(rest.V.rows()) + " vertices");
      corners_[3 * f + k] = v;
    }
  const auto report = mesh::manifold_report(rest.F, static_cast<int>(rest.V.rows()));
  if (!report.closed_manifold() || !report.consistently_oriented())
    throw UsageError("turgor: the mesh must be closed and consistently oriented to enclose a volume (" +
                     report.describe() + ")");
  const double v = signed_volume(std::span<const double>(rest.V.data(), rest.V.size()), corners_);
  if (!(v > 0))
    throw UsageError("turgor: the faces are oriented inward (signed volume " + std::to_string(v) +
                     " <= 0); orient them outward");
}

double TurgorPressure::energy(std::span<const double> x) const {
  check_sizes(x);
  return -turgor_ * signed_volume(x, corners_);
}

void TurgorPressure::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const double* X = x.data();
  double* G = g.data();
  const double s = -turgor_ / 6.0;
  const std::size_t nf = corners_.size() / 3;
  for (std::size_t f = 0; f < nf; ++f) {
    const int* q = &corners_[3 * f];
    for (int i = 0; i < 3; ++i) {  // dV/dx_a = (b x c)/6, cyclic
      const double* b = X + 3 * q[(i + 1) % 3];
      const double* c = X + 3 * q[(i + 2) % 3];
      double* ga = G + 3 * q[i];
      ga[0] += s * (b[1] * c[2] - b[2] * c[1]);
      ga[1] += s * (b[2] * c[0] - b[0] * c[2]);
      ga[2] += s * (b[0] * c[1] - b[1] * c[0]);
    }
  }
}

}  // namespace cmp::shell
