#include "shell/turgor_pressure.hpp"

#include "shell/shell_partition.hpp"

#include "core/errors.hpp"
#include "mesh/manifold.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::shell {

namespace {
inline double triple(const double* a, const double* b, const double* c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
// The columns one gradient pass reads and writes.
struct FaceArrays {
  const double* x;
  const int *q0, *q1, *q2, *shell;
  const double* scale;  // per shell: -Pi/6
};

// The force pass on one tile (element_assembly.hpp): dV/dx_a = (b x c)/6, cyclic, the same
// operations in every lane, so the same bits as one face at a time.
[[gnu::always_inline]] inline void pressure_tile(const double* __restrict P, const double* __restrict S,
                                                 double* __restrict O, int m) {
  for (int l = 0; l < m; ++l) {
    const auto p = [&](int row) { return P[row * kTile + l]; };
    const double s = S[l];
    for (int i = 0; i < 3; ++i) {
      const int b = 3 * ((i + 1) % 3), c = 3 * ((i + 2) % 3);
      O[(3 * i + 0) * kTile + l] = s * (p(b + 1) * p(c + 2) - p(b + 2) * p(c + 1));
      O[(3 * i + 1) * kTile + l] = s * (p(b + 2) * p(c + 0) - p(b + 0) * p(c + 2));
      O[(3 * i + 2) * kTile + l] = s * (p(b + 0) * p(c + 1) - p(b + 1) * p(c + 0));
    }
  }
}

[[gnu::target_clones("avx2", "default")]] void pressure_forces(const FaceArrays A, const CornerForces& out, long begin,
                                                               long end) {
  const CornerForces F = out;  // a local copy: the stores below cannot change it
  const int* corners[3] = {A.q0, A.q1, A.q2};
  alignas(64) double P[9 * kTile], O[9 * kTile], S[kTile];
  for (long t0 = begin; t0 < end; t0 += kTile) {
    const int m = static_cast<int>(std::min<long>(kTile, end - t0));
    load_tile<3>(A.x, corners, t0, m, P);
    for (int l = 0; l < m; ++l) S[l] = A.scale[A.shell[t0 + l]];
    pressure_tile(P, S, O, m);
    store_tile<3>(O, F, t0, m);
  }
}

}  // namespace

double signed_volume(std::span<const double> x, const std::vector<int>& corners) {
  const double* X = x.data();
  const std::size_t nf = corners.size() / 3;
  double sum = 0;
  for (std::size_t f = 0; f < nf; ++f)
    sum += triple(X + 3 * corners[3 * f], X + 3 * corners[3 * f + 1], X + 3 * corners[3 * f + 2]);
  return sum / 6.0;
}

TurgorPressure::TurgorPressure(const mesh::TriMesh& rest, const PressureParameters& p, PressureControl control)
    : control_(control), vertex_count_(rest.V.rows()) {
  const std::string style = name();
  validate(p, style.c_str());
  corners_.resize(3 * rest.F.rows());
  for (Eigen::Index f = 0; f < rest.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = rest.F(f, k);
      if (v < 0 || v >= rest.V.rows())
        throw UsageError(style + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                         " of a mesh with " + std::to_string(rest.V.rows()) + " vertices");
      corners_[3 * f + k] = v;
    }
  const auto report = mesh::manifold_report(rest.F, static_cast<int>(rest.V.rows()));
  if (!report.closed_manifold() || !report.consistently_oriented())
    throw UsageError(style + ": the mesh must be closed and consistently oriented to enclose a volume (" +
                     report.describe() + ")");
  const auto shells = shell_partition(rest.F, static_cast<int>(rest.V.rows()));
  face_shell_ = shells.face_shell;
  turgor_.assign(static_cast<std::size_t>(std::max(shells.shell_count, 1)), p.turgor);
  scale_.assign(turgor_.size(), 0.0);
  target_ = volumes(std::span<const double>(rest.V.data(), rest.V.size()));
  assembly_ = ElementAssembly(corners_, 3, vertex_count_);
  for (std::size_t s = 0; s < target_.size(); ++s)
    if (!(target_[s] > 0))
      throw UsageError(style + ": the faces are oriented inward (shell " + std::to_string(s) + ": signed volume " +
                       std::to_string(target_[s]) + " <= 0); orient them outward");
}

std::vector<double> TurgorPressure::volumes(std::span<const double> x) const {
  const double* X = x.data();
  std::vector<double> v(turgor_.size(), 0.0);
  const std::size_t nf = face_shell_.size();
  for (std::size_t f = 0; f < nf; ++f)
    v[face_shell_[f]] += triple(X + 3 * corners_[3 * f], X + 3 * corners_[3 * f + 1], X + 3 * corners_[3 * f + 2]);
  for (double& s : v) s /= 6.0;
  return v;
}

double TurgorPressure::energy(std::span<const double> x) const {
  check_sizes(x);
  const auto v = volumes(x);
  double e = 0;
  for (std::size_t s = 0; s < v.size(); ++s) e -= turgor_[s] * v[s];
  return e;
}

void TurgorPressure::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  for (std::size_t s = 0; s < turgor_.size(); ++s) scale_[s] = -turgor_[s] / 6.0;
  const FaceArrays A{x.data(), assembly_.corner(0), assembly_.corner(1), assembly_.corner(2), face_shell_.data(),
                     scale_.data()};
  const CornerForces F = assembly_.corner_forces();
  assembly_.assemble([&](long begin, long end) { pressure_forces(A, F, begin, end); }, g.data());
}

void TurgorPressure::set_turgor(double pi) {
  validate(PressureParameters{pi}, name().c_str());
  for (double& t : turgor_) t = pi;
}

void TurgorPressure::set_turgors(const std::vector<double>& pi) {
  if (pi.size() != turgor_.size())
    throw std::invalid_argument(name() + ": " + std::to_string(pi.size()) + " pressures for " +
                                std::to_string(turgor_.size()) + " shells");
  for (double t : pi) validate(PressureParameters{t}, name().c_str());
  turgor_ = pi;
}

void TurgorPressure::set_target_volumes(const std::vector<double>& v0) {
  if (v0.size() != target_.size())
    throw std::invalid_argument(name() + ": " + std::to_string(v0.size()) + " target volumes for " +
                                std::to_string(target_.size()) + " shells");
  for (double v : v0)
    if (!(v > 0 && std::isfinite(v))) throw UsageError(name() + ": a target volume must be positive and finite");
  target_ = v0;
}

double TurgorPressure::volume_error(std::span<const double> x) const {
  const auto v = volumes(x);
  double worst = 0;
  for (std::size_t s = 0; s < v.size(); ++s) worst = std::max(worst, std::abs(v[s] - target_[s]) / target_[s]);
  return worst;
}


}  // namespace cmp::shell
