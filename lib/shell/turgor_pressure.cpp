#include "shell/turgor_pressure.hpp"

#include "shell/element_assembly.hpp"
#include "shell/shell_partition.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"
#include "mesh/manifold.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::shell {

namespace {
inline double triple(const double* a, const double* b, const double* c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
// The force on each vertex of [begin, end), added into g: the sum over its faces, in face order,
// of -Pi/6 (b x c), (a, b, c) the face's corners from this vertex on in cyclic order. The same
// products and the same order of their sum as a pass over the faces that stores each corner's
// force in a slot and gathers the slots vertex by vertex (element_assembly.hpp), so the same
// bits; but a corner force costs six products here, and storing and reloading it cost more:
// the slot pass took as long as the membrane's (a quarter of a force evaluation of 50 shells
// of 2562 vertices) though it does a tenth of its arithmetic.
void pressure_gather(const double* __restrict x, const int* __restrict first, const int* __restrict ring,
                     const int* __restrict vertex_shell, const double* __restrict scale, long begin, long end,
                     double* __restrict g) {
  for (long v = begin; v < end; ++v) {
    const double s = scale[vertex_shell[v]];
    double sx = 0, sy = 0, sz = 0;
    for (int k = first[v]; k < first[v + 1]; ++k) {
      const double* b = x + 3L * ring[2 * k];
      const double* c = x + 3L * ring[2 * k + 1];
      sx += s * (b[1] * c[2] - b[2] * c[1]);
      sy += s * (b[2] * c[0] - b[0] * c[2]);
      sz += s * (b[0] * c[1] - b[1] * c[0]);
    }
    g[3 * v] += sx, g[3 * v + 1] += sy, g[3 * v + 2] += sz;
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
  shell_face_start_.assign(turgor_.size() + 1, 0);
  for (int s : face_shell_) ++shell_face_start_[s + 1];
  for (std::size_t s = 0; s < turgor_.size(); ++s) shell_face_start_[s + 1] += shell_face_start_[s];
  shell_faces_.resize(face_shell_.size());
  std::vector<int> next_face(shell_face_start_.begin(), shell_face_start_.end() - 1);
  for (std::size_t f = 0; f < face_shell_.size(); ++f) shell_faces_[next_face[face_shell_[f]]++] = static_cast<int>(f);
  target_ = volumes(std::span<const double>(rest.V.data(), rest.V.size()));
  build_rings(shells.face_shell);
  for (std::size_t s = 0; s < target_.size(); ++s)
    if (!(target_[s] > 0))
      throw UsageError(style + ": the faces are oriented inward (shell " + std::to_string(s) + ": signed volume " +
                       std::to_string(target_[s]) + " <= 0); orient them outward");
}

std::vector<double> TurgorPressure::volumes(std::span<const double> x) const {
  const double* X = x.data();
  const int shells = static_cast<int>(turgor_.size());
  std::vector<double> v(turgor_.size(), 0.0);
  // Each shell's faces in face order, shells on all threads where the other mesh passes are:
  // the same sums, so the same bits, on any thread count.
  const int chunks = std::min(shells, 64);
  for_each_chunk(chunks, ElementAssembly::runs_parallel(static_cast<long>(face_shell_.size())), [&](int c) {
    for (auto s = chunk_begin(shells, chunks, c); s < chunk_begin(shells, chunks, c + 1); ++s) {
      double sum = 0;
      for (int k = shell_face_start_[s]; k < shell_face_start_[s + 1]; ++k) {
        const int* f = corners_.data() + 3 * shell_faces_[k];
        sum += triple(X + 3 * f[0], X + 3 * f[1], X + 3 * f[2]);
      }
      v[s] = sum / 6.0;
    }
  });
  return v;
}

double TurgorPressure::energy(std::span<const double> x) const {
  check_sizes(x);
  const auto v = volumes(x);
  double e = 0;
  for (std::size_t s = 0; s < v.size(); ++s) e -= turgor_[s] * v[s];
  return e;
}

void TurgorPressure::build_rings(const std::vector<int>& face_shell) {
  // Each vertex's faces in face order, as the other two corners in cyclic order.
  first_.assign(static_cast<std::size_t>(vertex_count_) + 1, 0);
  for (int v : corners_) ++first_[v + 1];
  for (long v = 0; v < vertex_count_; ++v) first_[v + 1] += first_[v];
  ring_.resize(2 * corners_.size());
  vertex_shell_.assign(static_cast<std::size_t>(vertex_count_), 0);
  std::vector<int> next(first_.begin(), first_.end() - 1);
  const std::size_t nf = corners_.size() / 3;
  for (std::size_t f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      const int v = corners_[3 * f + i];
      const int k = next[v]++;
      ring_[2 * k] = corners_[3 * f + (i + 1) % 3];
      ring_[2 * k + 1] = corners_[3 * f + (i + 2) % 3];
      vertex_shell_[v] = face_shell[f];
    }
  vertex_chunks_ = static_cast<int>(std::max(1L, (vertex_count_ + kVertexChunk - 1) / kVertexChunk));
}

void TurgorPressure::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  for (std::size_t s = 0; s < turgor_.size(); ++s) scale_[s] = -turgor_[s] / 6.0;
  const int chunks = vertex_chunks_;
  // As the other mesh terms: on all threads from the same face count (element_assembly.hpp).
  const bool parallel = ElementAssembly::runs_parallel(static_cast<long>(face_shell_.size()));
  for_each_chunk(chunks, parallel, [&](int c) {
    pressure_gather(x.data(), first_.data(), ring_.data(), vertex_shell_.data(), scale_.data(),
                    chunk_begin(vertex_count_, chunks, c), chunk_begin(vertex_count_, chunks, c + 1), g.data());
  });
}

void TurgorPressure::volume_gradient(std::span<const double> x, std::span<double> n) const {
  check_sizes(x, n);
  std::fill(n.begin(), n.end(), 0.0);
  const std::vector<double> sixth(turgor_.size(), 1.0 / 6.0);  // dV/dx_a = sum_faces (b x c)/6
  const int chunks = vertex_chunks_;
  const bool parallel = ElementAssembly::runs_parallel(static_cast<long>(face_shell_.size()));
  for_each_chunk(chunks, parallel, [&](int c) {
    pressure_gather(x.data(), first_.data(), ring_.data(), vertex_shell_.data(), sixth.data(),
                    chunk_begin(vertex_count_, chunks, c), chunk_begin(vertex_count_, chunks, c + 1), n.data());
  });
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
