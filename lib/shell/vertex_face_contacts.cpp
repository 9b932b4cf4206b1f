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
  // The same box scaled by one factor on every side (the affine step of a compression) keeps
  // the list: its reference positions scale with the box (candidates_hold measures each move
  // from there), and what it tolerates shrinks by what the scaling took from its reach.
  if (list_valid_ && box_ && box_->periodic == periodic) {
    const double s = lengths[0] / box_->lengths[0];
    bool uniform = s > 0;
    for (int a = 1; a < 3; ++a) uniform = uniform && std::abs(lengths[a] / box_->lengths[a] - s) <= 1e-12 * s;
    if (uniform) {
      for (double& r : reference_) r *= s;
      list_scale_ *= s;
      tolerated_move_ = tolerated_move(list_scale_);
      list_valid_ = tolerated_move_ > 0;
      box_ = BoxSides{lengths, periodic};
      return;
    }
  }
  box_ = BoxSides{lengths, periodic};
  list_valid_ = false;
}

double VertexFaceContacts::tolerated_move(double scale) const {
  // A triangle at least delta + skin from x_i at the build is at least scale (delta + skin) from
  // it in the scaled reference, and stays beyond delta while x_i and its corners each move less
  // than half the difference (the point of the moved triangle with the old closest weights moves
  // no more than its corners); a little less, for round-off.
  return 0.5 * (scale * (delta_ + skin_) - delta_) * (1.0 - 1e-9);
}

namespace {
// The periodic images of the box: the periods of the minimum image (0 along an open axis),
// their inverses, and the shift of each image code (box sides times -1, 0, 1 per axis).
struct Images {
  double periods[3], inverse[3], shifts[27][3];
  explicit Images(const std::optional<ShellContactTerm::BoxSides>& box) {
    for (int a = 0; a < 3; ++a) {
      const bool wraps = box && box->periodic[a];
      periods[a] = wraps ? box->lengths[a] : 0.0;
      inverse[a] = wraps ? 1.0 / box->lengths[a] : 0.0;
    }
    for (int code = 0; code < 27; ++code)
      for (int a = 0, c = code; a < 3; ++a, c /= 3) shifts[code][a] = (c % 3 - 1) * periods[a];
  }
  // v - p in a candidate's image: the list's shift, or (code `straddles`, a triangle cut by
  // the box) each corner's own minimum image.
  void relative(const double* v, const double* p, int code, int straddles, double out[3]) const {
    if (code != straddles)
      for (int a = 0; a < 3; ++a) out[a] = v[a] - p[a] + shifts[code][a];
    else
      for (int a = 0; a < 3; ++a) out[a] = cmp::minimum_image(v[a] - p[a], periods[a], inverse[a]);
  }
};

// The point q of the triangle `corners` closest to p, relative to p (q - p), and its weights.
// The same operations in the list's build and in every evaluation: a contact the list keeps is
// found with the same bits.
[[gnu::always_inline]] inline Eigen::Vector3d closest_offset(const Images& images, const double* X, const int* corners, const double* p,
                                      int code, int straddles, Eigen::Vector3d& w) {
  Eigen::Vector3d corner[3];
  for (int k = 0; k < 3; ++k) images.relative(X + 3 * corners[k], p, code, straddles, corner[k].data());
  w = closest_triangle_weights(Eigen::Vector3d::Zero(), corner[0], corner[1], corner[2]);
  return w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2];
}
}  // namespace

bool VertexFaceContacts::parallel() const {
  // On all threads only where the membrane's passes are (about two triangles a vertex): below
  // that a pass is too short for a fork/join, which under load costs more than it saves.
  return 2 * static_cast<long>(shell_of_.size()) >= ElementAssembly::parallel_elements();
}

void VertexFaceContacts::build_candidates(std::span<const double> x) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  scratch_.resize(n, 3);
  std::copy(x.begin(), x.end(), scratch_.data());
  const Images images(box_);
  const double* periods = images.periods;
  const double* inverse = images.inverse;
  const double* X = scratch_.data();
  // reach_ per vertex: delta + the longest edge of its triangles (minimum image: a shell may
  // straddle a periodic face) / sqrt(3). Each face's longest edge, then each vertex's largest
  // over its faces, both on all threads (a max: the same on any thread count).
  const long nf = static_cast<long>(faces_.size() / 3);
  face_longest2_.resize(static_cast<std::size_t>(nf));
  const int face_chunks = static_cast<int>(std::max<long>(1, (nf + 2 * kChunkVertices - 1) / (2 * kChunkVertices)));
  std::vector<double> chunk_longest2(static_cast<std::size_t>(face_chunks), 0.0);
  for_each_chunk(face_chunks, parallel(), [&](int c) {
    double longest = 0;
    for (long f = chunk_begin(nf, face_chunks, c), end = chunk_begin(nf, face_chunks, c + 1); f < end; ++f) {
      double face2 = 0;
      for (int k = 0; k < 3; ++k) {
        double e[3];
        const double* a = X + 3 * faces_[3 * f + k];
        const double* b = X + 3 * faces_[3 * f + (k + 1) % 3];
        for (int c3 = 0; c3 < 3; ++c3) e[c3] = cmp::minimum_image(a[c3] - b[c3], periods[c3], inverse[c3]);
        face2 = std::max(face2, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      }
      face_longest2_[f] = face2;
      longest = std::max(longest, face2);
    }
    chunk_longest2[c] = longest;
  });
  const double longest2 = *std::max_element(chunk_longest2.begin(), chunk_longest2.end());
  const double third = 1.0 / 3.0 + 1e-12;  // a hair more than 1/3: round-off never hides a triangle
  reach_.resize(static_cast<std::size_t>(n));
  const int vchunks = vertex_chunks(n);
  for_each_chunk(vchunks, parallel(), [&](int c) {
    for (Eigen::Index v = chunk_begin(n, vchunks, c), end = chunk_begin(n, vchunks, c + 1); v < end; ++v) {
      double r = 0;
      for (int k = incident_start_[v]; k < incident_start_[v + 1]; ++k) r = std::max(r, face_longest2_[incident_[k]]);
      reach_[v] = delta_ + std::sqrt(r * third);
    }
  });
  const double longest = std::sqrt(longest2), base = delta_ + std::sqrt(longest2 * third);
  const double skin = kSkin * base, cutoff = base + skin;
  if (box_)
    for (int a = 0; a < 3; ++a)
      if (box_->periodic[a] && !(box_->lengths[a] >= 2.0 * (cutoff + longest)))
        throw ComputationError("hertz-faces: the periodic box side " + std::to_string(box_->lengths[a]) +
                               " is under 2 (delta + 0.58 longest edge + skin + longest edge) = " +
                               std::to_string(2.0 * (cutoff + longest)));
  // Broad phase: vertex pairs of different shells within the cutoff, kept in the direction(s)
  // i -> j where x_i is within j's reach + skin: a triangle within delta + skin of x_i has such
  // a corner j. Fixed chunks of cells on all threads, joined in order (the pairs of one pass).
  const neighbours::CellGrid grid = contact_grid(scratch_, cutoff, box_, "hertz-faces");
  const int cell_chunks = parallel() ? kBroadPhaseChunks : 1;
  std::vector<std::vector<int>> chunk_pairs(static_cast<std::size_t>(cell_chunks));
  for_each_chunk(cell_chunks, parallel(), [&](int c) {
    std::vector<int>& out = chunk_pairs[static_cast<std::size_t>(c)];
    out.clear();
    grid.for_each_pair_in_cells(scratch_, static_cast<int>(chunk_begin(grid.cell_count(), cell_chunks, c)),
                                static_cast<int>(chunk_begin(grid.cell_count(), cell_chunks, c + 1)),
                                [&](int i, int j, const Eigen::Vector3d&, double r2) {
                                  if (shell_of_[i] == shell_of_[j]) return;
                                  const double rj = reach_[j] + skin, ri = reach_[i] + skin;
                                  if (r2 < rj * rj) out.insert(out.end(), {i, j});
                                  if (r2 < ri * ri) out.insert(out.end(), {j, i});
                                });
  });
  pairs_.clear();
  for (const std::vector<int>& out : chunk_pairs) pairs_.insert(pairs_.end(), out.begin(), out.end());
  std::vector<int> partner_start(static_cast<std::size_t>(n) + 1, 0), partners(pairs_.size() / 2);
  for (std::size_t k = 0; k < pairs_.size(); k += 2) ++partner_start[pairs_[k] + 1];
  for (Eigen::Index v = 0; v < n; ++v) partner_start[v + 1] += partner_start[v];
  std::vector<int> next(partner_start.begin(), partner_start.end() - 1);
  for (std::size_t k = 0; k < pairs_.size(); k += 2) partners[next[pairs_[k]]++] = pairs_[k + 1];
  // Narrow phase, per fixed chunk of vertices on all threads: the triangles around each
  // vertex's partners, ascending, each once, with their periodic image seen from x_i (fixed
  // while the list holds: every candidate lies far inside half a box side; code (n_x + 1) +
  // 3 (n_y + 1) + 9 (n_z + 1) for a shift of n box sides, or kStraddles when the corners sit in
  // different images); kept only when the triangle is within delta + skin of x_i. Chunks are
  // joined in order: the same list on any thread count.
  const int chunks = vertex_chunks(n);
  std::vector<std::vector<int>> kept(static_cast<std::size_t>(chunks));
  std::vector<std::vector<std::uint8_t>> kept_images(static_cast<std::size_t>(chunks));
  std::vector<std::vector<double>> kept_gaps(static_cast<std::size_t>(chunks));
  candidate_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  const double keep2 = (delta_ + skin) * (delta_ + skin);
  for_each_chunk(chunks, parallel(), [&](int c) {
    std::vector<int> mine;
    std::vector<int>& faces = kept[static_cast<std::size_t>(c)];
    std::vector<std::uint8_t>& codes = kept_images[static_cast<std::size_t>(c)];
    std::vector<double>& gaps = kept_gaps[static_cast<std::size_t>(c)];
    for (Eigen::Index i = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); i < end; ++i) {
      mine.clear();
      for (int t = partner_start[i]; t < partner_start[i + 1]; ++t) {
        const int j = partners[t];
        mine.insert(mine.end(), incident_.begin() + incident_start_[j], incident_.begin() + incident_start_[j + 1]);
      }
      std::sort(mine.begin(), mine.end());
      mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
      const double* p = X + 3 * i;
      int count = 0;
      for (int f : mine) {
        int code = -1;
        for (int k = 0; k < 3 && code != kStraddles; ++k) {
          const double* v = X + 3 * faces_[3 * f + k];
          int cc = 0;
          for (int a = 2; a >= 0; --a) {
            const double raw = v[a] - p[a];
            // The box sides to add for the minimum image: minimum_image(raw) = raw - L nearbyint(raw / L).
            const long shift = periods[a] > 0 ? -static_cast<long>(std::nearbyint(raw * inverse[a])) : 0;
            cc = 3 * cc + static_cast<int>(shift + 1);
            if (shift < -1 || shift > 1) cc = -1000;
          }
          code = cc < 0 || (code >= 0 && code != cc) ? kStraddles : cc;
        }
        Eigen::Vector3d w;
        const Eigen::Vector3d q = closest_offset(images, X, faces_.data() + 3 * f, p, code, kStraddles, w);
        const double q2 = q.squaredNorm();
        if (!(q2 < keep2)) continue;
        faces.push_back(f);
        codes.push_back(static_cast<std::uint8_t>(code));
        gaps.push_back(std::sqrt(q2));
        ++count;
      }
      candidate_start_[i + 1] = count;
    }
  });
  for (Eigen::Index v = 0; v < n; ++v) candidate_start_[v + 1] += candidate_start_[v];
  candidates_.clear();
  candidate_images_.clear();
  candidate_gap_.clear();
  for (int c = 0; c < chunks; ++c) {
    candidates_.insert(candidates_.end(), kept[c].begin(), kept[c].end());
    candidate_images_.insert(candidate_images_.end(), kept_images[c].begin(), kept_images[c].end());
    candidate_gap_.insert(candidate_gap_.end(), kept_gaps[c].begin(), kept_gaps[c].end());
  }
  reference_.assign(x.begin(), x.end());
  moved_.assign(static_cast<std::size_t>(n), 0.0);
  face_moved_.assign(faces_.size() / 3, 0.0);
  skin_ = skin;
  list_scale_ = 1.0;
  ++list_builds_;
  tolerated_move_ = tolerated_move(1.0);
  list_valid_ = true;
}

bool VertexFaceContacts::candidates_hold(std::span<const double> x) const {
  if (!list_valid_ || reference_.size() != x.size()) return false;
  // Every vertex's move from the reference (collect() bounds each candidate's distance by it),
  // per fixed chunk on all threads; the list holds while the largest is under the tolerance.
  const long n = static_cast<long>(x.size() / 3);
  const int chunks = vertex_chunks(n);
  moved_.resize(static_cast<std::size_t>(n));
  std::vector<char> within(static_cast<std::size_t>(chunks), 1);
  for_each_chunk(chunks, parallel(), [&](int c) {
    bool ok = true;
    for (long v = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); v < end; ++v) {
      const double dx = x[3 * v] - reference_[3 * v], dy = x[3 * v + 1] - reference_[3 * v + 1],
                   dz = x[3 * v + 2] - reference_[3 * v + 2];
      moved_[v] = std::sqrt(dx * dx + dy * dy + dz * dz);
      ok = ok && moved_[v] < tolerated_move_;  // false for a NaN too
    }
    within[c] = ok;
  });
  if (!std::all_of(within.begin(), within.end(), [](char ok) { return ok != 0; })) return false;
  // Each face's largest corner move: one load per candidate in collect() instead of four.
  const long nf = static_cast<long>(faces_.size() / 3);
  face_moved_.resize(static_cast<std::size_t>(nf));
  for_each_chunk(chunks, parallel(), [&](int c) {
    for (long f = chunk_begin(nf, chunks, c), end = chunk_begin(nf, chunks, c + 1); f < end; ++f)
      face_moved_[f] = std::max({moved_[faces_[3 * f]], moved_[faces_[3 * f + 1]], moved_[faces_[3 * f + 2]]});
  });
  return true;
}

void VertexFaceContacts::collect(std::span<const double> x) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  const int chunks = vertex_chunks(n);
  records_.resize(static_cast<std::size_t>(chunks));
  for (auto& r : records_) r.clear();
  if (n == 0 || faces_.empty()) return;
  if (!candidates_hold(x)) build_candidates(x);
  const Images images(box_);
  const double* X = x.data();
  const double delta2 = delta_ * delta_;
  for_each_chunk(chunks, parallel(), [&](int c) {
    std::vector<Record>& out = records_[static_cast<std::size_t>(c)];
    for (Eigen::Index i = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); i < end; ++i) {
      const double* p = X + 3 * i;
      for (int s = candidate_start_[i]; s < candidate_start_[i + 1]; ++s) {
        const int f = candidates_[s];
        // The triangle was at candidate_gap_ from x_i when the list was built (list_scale_
        // times that in the scaled reference), and a distance to a triangle changes by at most
        // the move of the point plus the largest move of a corner: out of reach, no test needed
        // (a contact is never skipped, so the records are those of a full pass).
        const double reach = list_scale_ * candidate_gap_[s] - moved_[i] - face_moved_[f];
        if (reach > kSkipMargin * delta_) continue;
        Eigen::Vector3d w;
        const Eigen::Vector3d q = closest_offset(images, X, faces_.data() + 3 * f, p, candidate_images_[s], kStraddles, w);
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
    for (const Record& r : chunk) sum += hertz_energy(hertz_prefactor(estar_, rstar_), delta_ - r.r);
    total += sum;
  }
  return total;
}

void VertexFaceContacts::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  collect(x);
  const int chunks = static_cast<int>(records_.size());
  double* G = g.data();
  // dU/dp = -U'(h) d/r; 0 for p on the triangle (no direction; a set of measure zero).
  const auto factor_of = [&](const Record& r) { return r.r > 0 ? -hertz_force(hertz_prefactor(estar_, rstar_), delta_ - r.r) / r.r : 0.0; };
  // A record adds s d to its vertex and takes w_k s d from each corner k of its triangle with
  // w_k > 0 (a corner of weight 0 gets nothing), in record order into `out`; `touched` (if
  // given) flags the blocks of kChunkVertices vertices written.
  const auto scatter = [&](const std::vector<Record>& in, double* out, char* touched) {
    for (const Record& r : in) {
      const double s = factor_of(r);
      if (s == 0) continue;
      const int* corner = faces_.data() + 3 * r.face;
      for (int a = 0; a < 3; ++a) out[3 * r.i + a] += s * r.d[a];
      if (touched && !touched[r.i / kChunkVertices]) touched[r.i / kChunkVertices] = 1;
      for (int m = 0; m < 3; ++m)
        if (r.w[m] > 0) {
          for (int a = 0; a < 3; ++a) out[3 * corner[m] + a] -= r.w[m] * (s * r.d[a]);
          if (touched && !touched[corner[m] / kChunkVertices]) touched[corner[m] / kChunkVertices] = 1;
        }
    }
  };
  if (!parallel()) {
    for (const std::vector<Record>& in : records_) scatter(in, G, nullptr);
    return;
  }
  // Large systems (whatever the thread count): the corners of a record's triangle may lie in
  // any chunk, so the chunks of records are cut into kScatterSlabs slabs, each scattered in
  // order into a gradient of its own on all threads; then every entry of g adds the slabs
  // that wrote its block, in slab order, and clears them for the next call: the same bits on
  // any thread count.
  const std::size_t size = g.size();
  const long blocks = (static_cast<long>(size / 3) + kChunkVertices - 1) / kChunkVertices;
  // Each slab's flags on cache lines of their own: two threads writing one line would pass it
  // back and forth at every contact.
  const long stride = (blocks + 127) / 64 * 64;  // at least 64 bytes between slabs
  if (slab_gradients_.size() != kScatterSlabs * size) {
    slab_gradients_.assign(kScatterSlabs * size, 0.0);
    slab_touched_.assign(static_cast<std::size_t>(kScatterSlabs * stride + 64), 0);
  }
  for_each_chunk(kScatterSlabs, true, [&](int k) {
    for (int c = static_cast<int>(chunk_begin(chunks, kScatterSlabs, k)); c < chunk_begin(chunks, kScatterSlabs, k + 1); ++c)
      scatter(records_[static_cast<std::size_t>(c)], slab_gradients_.data() + k * size, slab_touched_.data() + 64 + k * stride);
  });
  for_each_chunk(static_cast<int>(blocks), true, [&](int b) {
    const std::size_t begin = 3 * static_cast<std::size_t>(b) * kChunkVertices,
                      end = std::min(size, 3 * static_cast<std::size_t>(b + 1) * kChunkVertices);
    for (int k = 0; k < kScatterSlabs; ++k) {
      char& touched = slab_touched_[static_cast<std::size_t>(64 + k * stride + b)];
      if (!touched) continue;
      double* slab = slab_gradients_.data() + k * size;
      for (std::size_t e = begin; e < end; ++e) {
        G[e] += slab[e];
        slab[e] = 0;
      }
      touched = 0;
    }
  });
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
                     Eigen::Vector3d(r.d[0], r.d[1], r.d[2]), r.r, h, hertz_force(hertz_prefactor(estar_, rstar_), h)});
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
