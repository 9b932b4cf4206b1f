#include "mesh/inside_query.hpp"

#include "mesh/point_in_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::mesh {

namespace {
// The ray runs along an oblique direction, not an axis: meshes built on a lattice or copied
// along an axis (a stack of equal shells) would otherwise put points exactly over one another's
// shadow corners. Rows of a rotation (about (1, 2, 3) by 1 radian).
constexpr double kTurn[3][3] = {{0.5731378554489869, -0.6090066421373934, 0.5482918096086},
                                {0.7403488404607821, 0.6716445041915284, -0.027879282947946227},
                                {-0.35127851212351696, 0.42190587791811224, 0.8358222520957642}};
inline void turned(const double* v, double out[3]) {
  for (int r = 0; r < 3; ++r) out[r] = kTurn[r][0] * v[0] + kTurn[r][1] * v[1] + kTurn[r][2] * v[2];
}
}  // namespace

InsideQuery::InsideQuery(const double* x, const FaceMatrix& F, Eigen::Index face_begin, Eigen::Index face_end)
    : x_(x), F_(F), begin_(face_begin), end_(face_end) {
  const long n = static_cast<long>(face_end - face_begin);
  corners_.resize(9 * static_cast<std::size_t>(std::max(n, 0L)));
  double z0 = 0, z1 = 0;
  for (long f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      double* v = corners_.data() + 9 * f + 3 * k;
      turned(x + 3 * F(face_begin + f, k), v);
      if (f == 0 && k == 0) x0_ = x1_ = v[0], y0_ = y1_ = v[1], z0 = z1 = v[2];
      x0_ = std::min(x0_, v[0]), x1_ = std::max(x1_, v[0]);
      y0_ = std::min(y0_, v[1]), y1_ = std::max(y1_, v[1]);
      z0 = std::min(z0, v[2]), z1 = std::max(z1, v[2]);
    }
  // Round-off of a side test is a few ulps of |a - p| |b - p|, of a crossing height a few ulps
  // of the extent: 1e-10 of those leaves a wide margin and almost never triggers.
  const double extent = std::max({x1_ - x0_, y1_ - y0_, z1 - z0, 1e-300});
  side_tolerance_ = 1e-10 * extent * extent;
  height_tolerance_ = 1e-10 * extent;
  // About two faces per cell: a closed surface casts each point's shadow twice or so.
  const double area = std::max((x1_ - x0_) * (y1_ - y0_), 1e-300);
  cell_ = std::max(std::sqrt(2.0 * area / std::max(n, 1L)), 1e-12 * extent);
  nx_ = std::clamp(static_cast<int>((x1_ - x0_) / cell_) + 1, 1, 4096);
  ny_ = std::clamp(static_cast<int>((y1_ - y0_) / cell_) + 1, 1, 4096);
  const auto column = [&](double v) { return std::clamp(static_cast<int>((v - x0_) / cell_), 0, nx_ - 1); };
  const auto row = [&](double v) { return std::clamp(static_cast<int>((v - y0_) / cell_), 0, ny_ - 1); };
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> next(cell_start_.begin(), cell_start_.end() - 1);
    if (pass == 1) cell_faces_.resize(static_cast<std::size_t>(cell_start_.back()));
    for (long f = 0; f < n; ++f) {
      const double* c = corners_.data() + 9 * f;
      const int i0 = column(std::min({c[0], c[3], c[6]})), i1 = column(std::max({c[0], c[3], c[6]}));
      const int j0 = row(std::min({c[1], c[4], c[7]})), j1 = row(std::max({c[1], c[4], c[7]}));
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const std::size_t cell = static_cast<std::size_t>(j) * nx_ + i;
          if (pass == 0)
            ++cell_start_[cell + 1];
          else
            cell_faces_[next[cell]++] = static_cast<int>(f);
        }
    }
    if (pass == 0)
      for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c) cell_start_[c + 1] += cell_start_[c];
  }
}

bool InsideQuery::inside(const Eigen::Vector3d& point) const {
  if (corners_.empty()) return false;
  double p[3];
  turned(point.data(), p);
  // Outside the shadows' bounding box (with a margin) the ray meets no face.
  const double margin = 1e-9 * cell_;
  if (p[0] < x0_ - margin || p[0] > x1_ + margin || p[1] < y0_ - margin || p[1] > y1_ + margin) return false;
  const int i = std::clamp(static_cast<int>((p[0] - x0_) / cell_), 0, nx_ - 1);
  const int j = std::clamp(static_cast<int>((p[1] - y0_) / cell_), 0, ny_ - 1);
  const std::size_t cell = static_cast<std::size_t>(j) * nx_ + i;
  int crossings = 0;
  for (int s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
    const double* c = corners_.data() + 9 * cell_faces_[s];
    if (std::max({c[2], c[5], c[8]}) < p[2] - height_tolerance_) continue;  // wholly below p
    // Side of p's shadow from each shadow edge (a, b): (a - p) x (b - p), z component.
    double side[3];
    for (int k = 0; k < 3; ++k) {
      const double* a = c + 3 * k;
      const double* b = c + 3 * ((k + 1) % 3);
      side[k] = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]);
    }
    int positive = 0, negative = 0;
    for (double v : side) {
      positive += v > side_tolerance_;
      negative += v < -side_tolerance_;
    }
    if (positive > 0 && negative > 0) continue;  // clearly outside this shadow
    if (positive + negative < 3) {               // on a shadow's edge or corner, within round-off
      ++undecided_;
      return winding_number(x_, F_, begin_, end_, point) > 0.5;
    }
    // Inside the shadow: the face's height over p's shadow, from the barycentric weights
    // (side[k] is twice the area opposite corner k + 2).
    const double z = (side[1] * c[2] + side[2] * c[5] + side[0] * c[8]) / (side[0] + side[1] + side[2]);
    if (std::abs(z - p[2]) <= height_tolerance_) {
      ++undecided_;
      return winding_number(x_, F_, begin_, end_, point) > 0.5;
    }
    if (z > p[2]) crossings += positive == 3 ? 1 : -1;
  }
  return crossings > 0;
}

}  // namespace cmp::mesh
