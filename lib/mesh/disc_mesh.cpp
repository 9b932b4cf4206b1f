#include "mesh/disc_mesh.hpp"

#include "mesh/planar_delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace cmp::mesh {

namespace {
constexpr double kInset = 0.6;  // lattice vertices kept at r < R - kInset a

struct Points {
  std::vector<double> x, y;
  std::vector<int> rim;
  int centre = 0;
};

Points disc_points(double R, double a) {
  Points p;
  const double h = a * std::sqrt(3.0) / 2;
  const int rows = static_cast<int>(std::ceil(R / h)) + 1, cols = static_cast<int>(std::ceil(R / a)) + 2;
  const double cut = R - kInset * a;
  for (int j = -rows; j <= rows; ++j)
    for (int i = -cols; i <= cols; ++i) {
      const double x = (i + 0.5 * (std::abs(j) % 2)) * a, y = j * h;
      if (x * x + y * y < cut * cut) {
        if (i == 0 && j == 0) p.centre = static_cast<int>(p.x.size());
        p.x.push_back(x);
        p.y.push_back(y);
      }
    }
  const int m = std::max(6, static_cast<int>(std::lround(2 * M_PI * R / a)));
  for (int k = 0; k < m; ++k) {
    p.rim.push_back(static_cast<int>(p.x.size()));
    p.x.push_back(R * std::cos(2 * M_PI * k / m));
    p.y.push_back(R * std::sin(2 * M_PI * k / m));
  }
  return p;
}

VertexMatrix to_matrix(const Points& p) {
  VertexMatrix V(static_cast<Eigen::Index>(p.x.size()), 3);
  for (std::size_t i = 0; i < p.x.size(); ++i) V.row(static_cast<Eigen::Index>(i)) << p.x[i], p.y[i], 0.0;
  return V;
}
}  // namespace

DiscMesh disc_mesh_with_spacing(double R, double a) {
  if (!(std::isfinite(R) && R > 0 && std::isfinite(a) && a > 0 && a <= 0.5 * R))
    throw std::invalid_argument("disc_mesh: needs R > 0 and 0 < a <= R/2");
  Points p = disc_points(R, a);
  DiscMesh d;
  d.mesh.V = to_matrix(p);
  d.mesh.F = planar_delaunay(d.mesh.V);
  // Laplacian smoothing of the lattice vertices near the rim (the band between the clipped
  // lattice and the ring is irregular), then triangulate again.
  const int nv = static_cast<int>(d.mesh.V.rows());
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<double> sx(nv, 0), sy(nv, 0);
    std::vector<int> cnt(nv, 0);
    for (Eigen::Index f = 0; f < d.mesh.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int u = d.mesh.F(f, k), v = d.mesh.F(f, (k + 1) % 3);
        sx[u] += d.mesh.V(v, 0), sy[u] += d.mesh.V(v, 1), ++cnt[u];
        sx[v] += d.mesh.V(u, 0), sy[v] += d.mesh.V(u, 1), ++cnt[v];
      }
    const int first_rim = p.rim.front();
    for (int v = 0; v < first_rim; ++v) {
      const double r = std::hypot(d.mesh.V(v, 0), d.mesh.V(v, 1));
      if (r > R - 2 * a && cnt[v] > 0) d.mesh.V.row(v) << sx[v] / cnt[v], sy[v] / cnt[v], 0.0;
    }
    d.mesh.F = planar_delaunay(d.mesh.V);
  }
  d.rim = p.rim;
  d.centre = p.centre;
  d.spacing = a;
  return d;
}

DiscMesh disc_mesh(double R, long vertices) {
  if (!(std::isfinite(R) && R > 0) || vertices < 19) throw std::invalid_argument("disc_mesh: needs R > 0 and >= 19 vertices");
  // Area per lattice vertex (sqrt(3)/2) a^2: start there and correct the spacing a few times.
  double a = std::min(0.5 * R, R * std::sqrt(M_PI / (std::sqrt(3.0) / 2 * vertices)));
  double best = a;
  long best_err = -1;
  for (int it = 0; it < 8; ++it) {
    const Points p = disc_points(R, a);
    const long count = static_cast<long>(p.x.size());
    const long err = std::abs(count - vertices);
    if (best_err < 0 || err < best_err) best = a, best_err = err;
    if (err == 0) break;
    a = std::min(0.5 * R, a * std::sqrt(static_cast<double>(count) / vertices));
  }
  return disc_mesh_with_spacing(R, best);
}

}  // namespace cmp::mesh
