#include "lbm/sphere_lattice.hpp"

#include "lbm/d3q19.hpp"

#include "core/errors.hpp"
#include "core/random.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace cmp::lbm {

namespace {

// Minimum-image difference a - b on a period n.
double wrap(double d, int n) { return d - n * std::round(d / n); }

int mod(int a, int n) { return ((a % n) + n) % n; }

}  // namespace

PoreLattice periodic_spheres(int nx, int ny, int nz, const std::vector<LatticeSphere>& spheres) {
  if (nx < 1 || ny < 1 || nz < 1) throw UsageError("periodic_spheres: box sizes must be positive");
  PoreLattice p = open_box(nx, ny, nz);
  // owner[i]: index of one sphere containing solid node i (for its wall distances).
  auto owner = std::make_shared<std::vector<int>>(static_cast<std::size_t>(p.nodes()), -1);
  const int n[3] = {nx, ny, nz};
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    const LatticeSphere& sp = spheres[s];
    const double c[3] = {sp.x, sp.y, sp.z};
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = static_cast<int>(std::floor(c[a] - sp.r));
      hi[a] = static_cast<int>(std::ceil(c[a] + sp.r));
      if (hi[a] - lo[a] >= n[a]) {  // sphere wider than the box: every coordinate once
        lo[a] = 0;
        hi[a] = n[a] - 1;
      }
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const double dx = wrap(x - c[0], nx), dy = wrap(y - c[1], ny), dz = wrap(z - c[2], nz);
          if (dx * dx + dy * dy + dz * dz >= sp.r * sp.r) continue;
          const long i = p.index(mod(x, nx), mod(y, ny), mod(z, nz));
          p.fluid[static_cast<std::size_t>(i)] = 0;
          (*owner)[static_cast<std::size_t>(i)] = static_cast<int>(s);
        }
  }
  p.wall_fraction = [spheres, owner, nx, ny, nz](int x, int y, int z, int q) {
    const int sx = mod(x + kCx[q], nx), sy = mod(y + kCy[q], ny), sz = mod(z + kCz[q], nz);
    const int s = (*owner)[static_cast<std::size_t>(sx + static_cast<long>(nx) * (sy + static_cast<long>(ny) * sz))];
    if (s < 0) return 0.5;
    const LatticeSphere& sp = spheres[static_cast<std::size_t>(s)];
    // |d + t c|^2 = r^2, d = node - centre: the smaller root is where the link enters the sphere.
    const double d[3] = {wrap(x - sp.x, nx), wrap(y - sp.y, ny), wrap(z - sp.z, nz)};
    const double cq[3] = {double(kCx[q]), double(kCy[q]), double(kCz[q])};
    const double a = cq[0] * cq[0] + cq[1] * cq[1] + cq[2] * cq[2];
    const double b = d[0] * cq[0] + d[1] * cq[1] + d[2] * cq[2];
    const double c = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - sp.r * sp.r;
    const double disc = std::max(b * b - a * c, 0.0);
    const double t = (-b - std::sqrt(disc)) / a;
    return std::clamp(t, 1e-6, 1.0);
  };
  return p;
}

PoreLattice simple_cubic_array(int n, double solid_fraction) {
  const double r = n * std::cbrt(3 * solid_fraction / (4 * std::numbers::pi));
  const double c = 0.5 * (n - 1);
  return periodic_spheres(n, n, n, {{c, c, c, r}});
}

PoreLattice random_sphere_box(int n, double target_porosity, std::uint64_t seed) {
  Random rng(seed);
  std::vector<LatticeSphere> s;
  const double r = n / 12.0;
  PoreLattice p = open_box(n, n, n);
  while (true) {
    for (int k = 0; k < 16; ++k) s.push_back({rng.uniform(0, n), rng.uniform(0, n), rng.uniform(0, n), r});
    p = periodic_spheres(n, n, n, s);
    if (p.porosity() < target_porosity) break;
  }
  p.wall_fraction = nullptr;
  return p;
}

namespace {
constexpr DragReference kZickHomsy[] = {{0.027, 2.008}, {0.064, 2.810}, {0.125, 4.292}, {0.216, 7.442},
                                        {0.343, 15.4},  {0.45, 28.1},   {0.5236, 42.1}};
}  // namespace

std::span<const DragReference> zick_homsy_simple_cubic() { return kZickHomsy; }

double hasimoto_drag(double c) {
  return 1 / (1 - 1.7601 * std::cbrt(c) + c - 1.5593 * c * c + 3.9799 * std::pow(c, 8.0 / 3) -
              3.0734 * std::pow(c, 10.0 / 3));
}

double sphere_array_kappa(int n, double c, double K) {
  const double a = n * std::cbrt(3 * c / (4 * std::numbers::pi));
  return std::pow(n, 3) / (6 * std::numbers::pi * a * K);
}

}  // namespace cmp::lbm
