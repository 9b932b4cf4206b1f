#include "mesh/planar_delaunay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cmp::mesh {

namespace {
struct Tri {
  std::array<int, 3> v;
  double cx, cy, r2;  // circumcircle
};

double orient(const double* a, const double* b, const double* c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
}  // namespace

FaceMatrix planar_delaunay(const VertexMatrix& P) {
  const int n = static_cast<int>(P.rows());
  if (n < 3) throw std::invalid_argument("planar_delaunay: needs at least 3 points");
  // Points plus the three corners of a triangle far outside them.
  std::vector<std::array<double, 2>> pts(n + 3);
  double lo[2] = {P(0, 0), P(0, 1)}, hi[2] = {P(0, 0), P(0, 1)};
  for (int i = 0; i < n; ++i) {
    pts[i] = {P(i, 0), P(i, 1)};
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], P(i, k)), hi[k] = std::max(hi[k], P(i, k));
  }
  const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
  const double d = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300}) * 1e4;
  pts[n] = {cx - 2 * d, cy - d};
  pts[n + 1] = {cx + 2 * d, cy - d};
  pts[n + 2] = {cx, cy + 2 * d};

  auto make = [&](int a, int b, int c) {
    if (orient(pts[a].data(), pts[b].data(), pts[c].data()) < 0) std::swap(b, c);
    const double ax = pts[a][0], ay = pts[a][1], bx = pts[b][0] - ax, by = pts[b][1] - ay, qx = pts[c][0] - ax,
                 qy = pts[c][1] - ay;
    const double D = 2 * (bx * qy - by * qx);
    const double ux = (qy * (bx * bx + by * by) - by * (qx * qx + qy * qy)) / D;
    const double uy = (bx * (qx * qx + qy * qy) - qx * (bx * bx + by * by)) / D;
    return Tri{{a, b, c}, ax + ux, ay + uy, ux * ux + uy * uy};
  };

  std::vector<Tri> tris{make(n, n + 1, n + 2)};
  std::vector<Tri> keep, bad;
  std::map<std::pair<int, int>, int> edges;  // directed edges of the cavity's triangles
  for (int i = 0; i < n; ++i) {
    const double x = pts[i][0], y = pts[i][1];
    keep.clear();
    bad.clear();
    for (const Tri& t : tris) {
      const double dx = x - t.cx, dy = y - t.cy;
      (dx * dx + dy * dy < t.r2 ? bad : keep).push_back(t);
    }
    if (bad.empty()) throw std::invalid_argument("planar_delaunay: duplicate or degenerate points");
    // Rounding can leave the cavity not star-shaped from the new point (near-cocircular
    // points): grow it across any boundary edge the point does not see until it is.
    for (;;) {
      edges.clear();
      for (const Tri& t : bad)
        for (int k = 0; k < 3; ++k) edges[{t.v[k], t.v[(k + 1) % 3]}] += 1;
      bool grown = false;
      for (const auto& [e, count] : edges) {
        if (edges.count({e.second, e.first})) continue;
        if (orient(pts[e.first].data(), pts[e.second].data(), pts[i].data()) > 0) continue;
        auto across = std::find_if(keep.begin(), keep.end(), [&](const Tri& t) {
          for (int k = 0; k < 3; ++k)
            if (t.v[k] == e.second && t.v[(k + 1) % 3] == e.first) return true;
          return false;
        });
        if (across == keep.end()) throw std::invalid_argument("planar_delaunay: duplicate or degenerate points");
        bad.push_back(*across);
        keep.erase(across);
        grown = true;
        break;
      }
      if (!grown) break;
    }
    for (const auto& [e, count] : edges)
      if (!edges.count({e.second, e.first})) keep.push_back(make(e.first, e.second, i));
    tris.swap(keep);
  }
  std::vector<std::array<int, 3>> out;
  for (const Tri& t : tris)
    if (t.v[0] < n && t.v[1] < n && t.v[2] < n) out.push_back(t.v);
  if (out.empty()) throw std::invalid_argument("planar_delaunay: the points are collinear");
  FaceMatrix F(static_cast<Eigen::Index>(out.size()), 3);
  for (std::size_t f = 0; f < out.size(); ++f) F.row(static_cast<Eigen::Index>(f)) << out[f][0], out[f][1], out[f][2];
  return F;
}

}  // namespace cmp::mesh
