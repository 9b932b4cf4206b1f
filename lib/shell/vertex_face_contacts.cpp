#include "shell/vertex_face_contacts.hpp"

#include "shell/element_assembly.hpp"
#include "shell/shell_partition.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"
#include "neighbours/cell_grid.hpp"


#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::shell {

VertexFaceContacts::VertexFaceContacts(const mesh::TriMesh& rest, const ContactParameters& p)
    : delta_(p.contact_distance), estar_(p.vertex_effective_modulus()), rstar_(0.5 * p.contact_distance) {
  validate(p, "hertz-faces");
  check_face_indices(rest, "hertz-faces");
  const int n = static_cast<int>(rest.V.rows());
  ShellPartition part = shell_partition(rest.F, n);
  shell_of_ = std::move(part.vertex_shell);
  face_shell_ = std::move(part.face_shell);
  const int nf = static_cast<int>(rest.F.rows());
  faces_.resize(3 * static_cast<std::size_t>(nf));
  incident_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      faces_[3 * f + k] = rest.F(f, k);
      ++incident_start_[rest.F(f, k) + 1];
    }
  for (int v = 0; v < n; ++v) incident_start_[v + 1] += incident_start_[v];
  incident_.resize(faces_.size());
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) incident_[next[faces_[3 * f + k]]++] = f;  // ascending faces per vertex
  if (p.box) set_box(*p.box, p.box_periodic);
}

void VertexFaceContacts::set_box(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) {
  for (int a = 0; a < 3; ++a) {
    if (!(lengths[a] > 0) || !std::isfinite(lengths[a]))
      throw UsageError("hertz-faces: box side " + std::to_string(lengths[a]) + " is not positive and finite");
    if (periodic[a] && !(lengths[a] >= 4.0 * delta_))
      throw UsageError("hertz-faces: the periodic box side " + std::to_string(lengths[a]) +
                       " is shorter than 4 contact distances (" + std::to_string(4.0 * delta_) + ")");
  }
  box_ = BoxSides{lengths, periodic};
  list_valid_ = false;
}

namespace {
// The periods of the minimum image (0 along an open axis) and their inverses.
void periods_of(const std::optional<ShellContactTerm::BoxSides>& box, double periods[3], double inverse[3]) {
  for (int a = 0; a < 3; ++a) {
    const bool wraps = box && box->periodic[a];
    periods[a] = wraps ? box->lengths[a] : 0.0;
    inverse[a] = wraps ? 1.0 / box->lengths[a] : 0.0;
  }
}
}  // namespace

void VertexFaceContacts::build_candidates(std::span<const double> x) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  scratch_.resize(n, 3);
  std::copy(x.begin(), x.end(), scratch_.data());
  double periods[3], inverse[3];
  periods_of(box_, periods, inverse);
  const double* X = scratch_.data();
  // reach_ per vertex: delta + the longest edge of its triangles (minimum image: a shell may
  // straddle a periodic face) / sqrt(3).
  reach_.assign(static_cast<std::size_t>(n), 0.0);
  double longest2 = 0;
  for (std::size_t f = 0; f < faces_.size(); f += 3) {
    double face2 = 0;
    for (int k = 0; k < 3; ++k) {
      double e[3];
      const double* a = X + 3 * faces_[f + k];
      const double* b = X + 3 * faces_[f + (k + 1) % 3];
      for (int c = 0; c < 3; ++c) e[c] = cmp::minimum_image(a[c] - b[c], periods[c], inverse[c]);
      face2 = std::max(face2, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    }
    for (int k = 0; k < 3; ++k) reach_[faces_[f + k]] = std::max(reach_[faces_[f + k]], face2);
    longest2 = std::max(longest2, face2);
  }
  const double third = 1.0 / 3.0 + 1e-12;  // a hair more than 1/3: round-off never hides a triangle
  for (double& r : reach_) r = delta_ + std::sqrt(r * third);
  const double longest = std::sqrt(longest2), base = delta_ + std::sqrt(longest2 * third);
  const double skin = 0.25 * base, cutoff = base + skin;
  if (box_)
    for (int a = 0; a < 3; ++a)
      if (box_->periodic[a] && !(box_->lengths[a] >= 2.0 * (cutoff + longest)))
        throw ComputationError("hertz-faces: the periodic box side " + std::to_string(box_->lengths[a]) +
                               " is under 2 (1.5 (delta + 0.58 longest edge) + longest edge) = " +
                               std::to_string(2.0 * (cutoff + longest)));
  // Vertex pairs of different shells within the cutoff (one pass over the cells, on one
  // thread), kept in the direction(s) i -> j where x_i is within j's reach + skin; then each
  // vertex's candidates: the triangles around its partners, ascending, each once.
  const neighbours::CellGrid grid = contact_grid(scratch_, cutoff, box_, "hertz-faces");
  pairs_.clear();
  grid.for_each_pair(scratch_, [&](int i, int j, const Eigen::Vector3d&, double r2) {
    if (shell_of_[i] == shell_of_[j]) return;
    const double rj = reach_[j] + skin, ri = reach_[i] + skin;
    if (r2 < rj * rj) pairs_.insert(pairs_.end(), {i, j});
    if (r2 < ri * ri) pairs_.insert(pairs_.end(), {j, i});
  });
  std::vector<int> partner_start(static_cast<std::size_t>(n) + 1, 0), partners(pairs_.size() / 2);
  for (std::size_t k = 0; k < pairs_.size(); k += 2) ++partner_start[pairs_[k] + 1];
  for (Eigen::Index v = 0; v < n; ++v) partner_start[v + 1] += partner_start[v];
  std::vector<int> next(partner_start.begin(), partner_start.end() - 1);
  for (std::size_t k = 0; k < pairs_.size(); k += 2) partners[next[pairs_[k]]++] = pairs_[k + 1];
  candidate_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  candidates_.clear();
  candidate_images_.clear();
  std::vector<int> mine;
  for (Eigen::Index i = 0; i < n; ++i) {
    mine.clear();
    for (int t = partner_start[i]; t < partner_start[i + 1]; ++t) {
      const int j = partners[t];
      mine.insert(mine.end(), incident_.begin() + incident_start_[j], incident_.begin() + incident_start_[j + 1]);
    }
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    candidates_.insert(candidates_.end(), mine.begin(), mine.end());
    // The periodic image of each candidate seen from x_i, fixed while the list holds (every
    // candidate lies far inside half a box side): code (n_x + 1) + 3 (n_y + 1) + 9 (n_z + 1)
    // for a shift of n box sides, or kStraddles when the corners sit in different images.
    const double* p = X + 3 * i;
    for (int f : mine) {
      int code = -1;
      for (int k = 0; k < 3 && code != kStraddles; ++k) {
        const double* v = X + 3 * faces_[3 * f + k];
        int c = 0;
        for (int a = 2; a >= 0; --a) {
          const double raw = v[a] - p[a];
          const long shift = periods[a] > 0 ? std::lround((cmp::minimum_image(raw, periods[a], inverse[a]) - raw) / periods[a]) : 0;
          c = 3 * c + static_cast<int>(shift + 1);
          if (shift < -1 || shift > 1) c = -1000;
        }
        code = c < 0 || (code >= 0 && code != c) ? kStraddles : c;
      }
      candidate_images_.push_back(static_cast<std::uint8_t>(code));
    }
    candidate_start_[i + 1] = static_cast<int>(candidates_.size());
  }
  active_faces_ = candidates_;
  std::sort(active_faces_.begin(), active_faces_.end());
  active_faces_.erase(std::unique(active_faces_.begin(), active_faces_.end()), active_faces_.end());
  reference_.assign(x.begin(), x.end());
  tolerated_move_ = skin / 3.2;  // > 2 (1 + 1/sqrt 3) times the largest move
  list_valid_ = true;
}

bool VertexFaceContacts::candidates_hold(std::span<const double> x) const {
  if (!list_valid_ || reference_.size() != x.size()) return false;
  const double limit2 = tolerated_move_ * tolerated_move_;
  for (std::size_t k = 0; k < x.size(); k += 3) {
    const double dx = x[k] - reference_[k], dy = x[k + 1] - reference_[k + 1], dz = x[k + 2] - reference_[k + 2];
    if (!(dx * dx + dy * dy + dz * dz < limit2)) return false;
  }
  return true;
}

void VertexFaceContacts::collect(std::span<const double> x) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  const int chunks = static_cast<int>(std::max<long>(1, (n + kChunkVertices - 1) / kChunkVertices));
  records_.resize(static_cast<std::size_t>(chunks));
  for (auto& r : records_) r.clear();
  if (n == 0 || faces_.empty()) return;
  if (!candidates_hold(x)) build_candidates(x);

  double periods[3], inverse[3];
  periods_of(box_, periods, inverse);
  const double* X = x.data();
  const double delta2 = delta_ * delta_;
  // Each candidate triangle's bounding sphere (centroid, largest corner distance): most
  // candidates are farther than delta from it and skip the closest-point test.
  bounds_.resize(faces_.size() / 3 * 4);
  const long na = static_cast<long>(active_faces_.size());
  const int face_chunks = static_cast<int>(std::max<long>(1, (na + kChunkVertices - 1) / kChunkVertices));
  // On all threads only where the membrane's passes are (about two triangles a vertex): below
  // that the search is too short for a fork/join, which under load costs more than it saves.
  const bool parallel = 2 * n >= ElementAssembly::parallel_elements();
  for_each_chunk(face_chunks, parallel, [&](int c) {
    for (long k = chunk_begin(na, face_chunks, c), end = chunk_begin(na, face_chunks, c + 1); k < end; ++k) {
      const long f = active_faces_[k];
      const double* a = X + 3 * faces_[3 * f];
      double e[2][3], g[3];
      for (int k = 0; k < 2; ++k) {
        const double* v = X + 3 * faces_[3 * f + 1 + k];
        for (int d = 0; d < 3; ++d) e[k][d] = cmp::minimum_image(v[d] - a[d], periods[d], inverse[d]);
      }
      for (int d = 0; d < 3; ++d) g[d] = (e[0][d] + e[1][d]) / 3.0;
      double r2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
      for (int k = 0; k < 2; ++k) {
        const double dx = e[k][0] - g[0], dy = e[k][1] - g[1], dz = e[k][2] - g[2];
        r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
      }
      double* b = bounds_.data() + 4 * f;
      for (int d = 0; d < 3; ++d) b[d] = a[d] + g[d];
      b[3] = std::sqrt(r2) * (1.0 + 1e-12) + delta_;  // the reach of the sphere: delta beyond it
    }
  });
  // The shift of each image code (box sides times -1, 0, 1 per axis).
  double shifts[27][3];
  for (int code = 0; code < 27; ++code)
    for (int a = 0, c = code; a < 3; ++a, c /= 3) shifts[code][a] = (c % 3 - 1) * periods[a];
  for_each_chunk(chunks, parallel, [&](int c) {
    std::vector<Record>& out = records_[static_cast<std::size_t>(c)];
    for (Eigen::Index i = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); i < end; ++i) {
      const double* p = X + 3 * i;
      for (int s = candidate_start_[i]; s < candidate_start_[i + 1]; ++s) {
        const int f = candidates_[s];
        const int code = candidate_images_[s];
        // Positions relative to p in the candidate's image: the list's shift, or (a triangle
        // cut by the box) each corner's own minimum image.
        const auto relative = [&](const double* v, double out[3]) {
          if (code != kStraddles)
            for (int a = 0; a < 3; ++a) out[a] = v[a] - p[a] + shifts[code][a];
          else
            for (int a = 0; a < 3; ++a) out[a] = cmp::minimum_image(v[a] - p[a], periods[a], inverse[a]);
        };
        const double* sphere = bounds_.data() + 4 * f;
        double centre[3];
        relative(sphere, centre);
        if (!(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2] < sphere[3] * sphere[3])) continue;
        Eigen::Vector3d corner[3];
        for (int k = 0; k < 3; ++k) relative(X + 3 * faces_[3 * f + k], corner[k].data());
        const Eigen::Vector3d w = closest_triangle_weights(Eigen::Vector3d::Zero(), corner[0], corner[1], corner[2]);
        const Eigen::Vector3d q = w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2];
        const double d2 = q.squaredNorm();
        if (!(d2 < delta2)) continue;
        out.push_back({static_cast<int>(i), f, {w[0], w[1], w[2]}, {-q[0], -q[1], -q[2]}, std::sqrt(d2)});
      }
    }
  });
}

double VertexFaceContacts::energy(std::span<const double> x) const {
  check_sizes(x);
  collect(x);
  double total = 0;
  for (const auto& chunk : records_) {
    double sum = 0;
    for (const Record& r : chunk) sum += hertz_energy(delta_ - r.r, estar_, rstar_);
    total += sum;
  }
  return total;
}

void VertexFaceContacts::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  collect(x);
  double* G = g.data();
  for (const auto& chunk : records_)
    for (const Record& r : chunk) {
      if (!(r.r > 0)) continue;  // p on the triangle: no direction (a set of measure zero)
      // dU/dp = -U'(h) d/r; each corner k takes -w_k dU/dp.
      const double s = -hertz_force(delta_ - r.r, estar_, rstar_) / r.r;
      const int* corner = faces_.data() + 3 * r.face;
      for (int a = 0; a < 3; ++a) {
        const double gp = s * r.d[a];
        G[3 * r.i + a] += gp;
        for (int k = 0; k < 3; ++k) G[3 * corner[k] + a] -= r.w[k] * gp;
      }
    }
}

std::vector<ShellContactTerm::Touch> VertexFaceContacts::touches(std::span<const double> x) const {
  check_sizes(x);
  collect(x);
  std::vector<Touch> out;
  for (const auto& chunk : records_)
    for (const Record& r : chunk) {
      const int* corner = faces_.data() + 3 * r.face;
      const double h = delta_ - r.r;
      out.push_back({r.i, {corner[0], corner[1], corner[2]}, Eigen::Vector3d(r.w[0], r.w[1], r.w[2]),
                     Eigen::Vector3d(r.d[0], r.d[1], r.d[2]), r.r, h, hertz_force(h, estar_, rstar_)});
    }
  return out;
}

std::vector<char> VertexFaceContacts::touching(std::span<const double> x) const {
  check_sizes(x);
  collect(x);
  std::vector<char> t(shell_of_.size(), 0);
  for (const auto& chunk : records_)
    for (const Record& r : chunk) {
      t[r.i] = 1;
      for (int k = 0; k < 3; ++k)
        if (r.w[k] > 0) t[faces_[3 * r.face + k]] = 1;
    }
  return t;
}

}  // namespace cmp::shell
