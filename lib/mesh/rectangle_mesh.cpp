#include "mesh/rectangle_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace cmp::mesh {

namespace {
// Columns along x and rows in y for spacing a.
struct Layout {
  int cols, rows;  // vertices of an even row; number of rows
};

Layout layout(double W, double H, double a) {
  const int cols = std::max(2, static_cast<int>(std::lround(W / a)) + 1);
  const double ax = W / (cols - 1);
  const int rows = std::max(2, static_cast<int>(std::lround(H / (ax * std::sqrt(3.0) / 2))) + 1);
  return {cols, rows};
}

long count(const Layout& l) { return static_cast<long>(l.rows) * l.cols + l.rows / 2; }
}  // namespace

RectangleMesh rectangle_mesh_with_spacing(double W, double H, double a) {
  if (!(std::isfinite(W) && std::isfinite(H) && W > 0 && H > 0 && std::isfinite(a) && a > 0 && a <= 0.5 * std::min(W, H)))
    throw std::invalid_argument("rectangle_mesh: needs W, H > 0 and 0 < a <= min(W, H)/2");
  const Layout l = layout(W, H, a);
  const double ax = W / (l.cols - 1), ay = H / (l.rows - 1);
  RectangleMesh m;
  std::vector<std::vector<int>> row(l.rows);
  std::vector<double> xs, ys;
  for (int j = 0; j < l.rows; ++j) {
    std::vector<double> x;
    if (j % 2 == 0) {
      for (int i = 0; i < l.cols; ++i) x.push_back(i == l.cols - 1 ? W : i * ax);
    } else {
      x.push_back(0.0);
      for (int i = 0; i + 1 < l.cols; ++i) x.push_back((i + 0.5) * ax);
      x.push_back(W);
    }
    const double y = j == l.rows - 1 ? H : j * ay;
    for (double xi : x) {
      row[j].push_back(static_cast<int>(xs.size()));
      xs.push_back(xi);
      ys.push_back(y);
    }
  }
  m.mesh.V.resize(static_cast<Eigen::Index>(xs.size()), 3);
  for (std::size_t v = 0; v < xs.size(); ++v) m.mesh.V.row(static_cast<Eigen::Index>(v)) << xs[v], ys[v], 0.0;
  // Zip each pair of rows: advance along whichever row's next vertex is further left (on a tie,
  // at the right edge, the row that keeps the half triangle right-angled); every
  // triangle (lower, lower next, upper) or (lower, upper next, upper) is counter-clockwise.
  std::vector<std::array<int, 3>> faces;
  for (int j = 0; j + 1 < l.rows; ++j) {
    const auto& lo = row[j];
    const auto& up = row[j + 1];
    std::size_t p = 0, q = 0;
    while (p + 1 < lo.size() || q + 1 < up.size()) {
      const bool advance_lower =
          q + 1 >= up.size() || (p + 1 < lo.size() && xs[lo[p + 1]] + 1e-12 * W < xs[up[q + 1]]) ||
          (p + 1 < lo.size() && std::abs(xs[lo[p + 1]] - xs[up[q + 1]]) <= 1e-12 * W && (j % 2 == 0));
      if (advance_lower) {
        faces.push_back({lo[p], lo[p + 1], up[q]});
        ++p;
      } else {
        faces.push_back({lo[p], up[q + 1], up[q]});
        ++q;
      }
    }
  }
  m.mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    m.mesh.F.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  for (int j = 0; j < l.rows; ++j) {
    m.left.push_back(row[j].front());
    m.right.push_back(row[j].back());
  }
  m.bottom = row.front();
  m.top = row.back();
  m.spacing = ax;
  return m;
}

RectangleMesh rectangle_mesh(double W, double H, long vertices) {
  if (!(std::isfinite(W) && std::isfinite(H) && W > 0 && H > 0) || vertices < 9)
    throw std::invalid_argument("rectangle_mesh: needs W, H > 0 and >= 9 vertices");
  // Scan the column count: the count grows monotonically with it.
  double best = 0.5 * std::min(W, H);
  long best_err = -1;
  for (int cols = 3; cols < 100000; ++cols) {
    const double a = W / (cols - 1);
    if (a > 0.5 * std::min(W, H)) continue;
    const long c = count(layout(W, H, a));
    const long err = std::abs(c - vertices);
    if (best_err < 0 || err < best_err) best = a, best_err = err;
    if (c > vertices) break;
  }
  return rectangle_mesh_with_spacing(W, H, best);
}

}  // namespace cmp::mesh
