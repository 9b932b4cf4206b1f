#include "voxel/porosity.hpp"

#include "core/minimum_image.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cmp::voxel {

double voxel_porosity(const std::vector<std::uint8_t>& pore) {
  if (pore.empty()) return 0;
  long n = 0;
  const long size = static_cast<long>(pore.size());
#pragma omp parallel for reduction(+ : n) schedule(static)
  for (long i = 0; i < size; ++i) n += pore[i] != 0;
  return static_cast<double>(n) / size;
}

double lens_volume(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0;
  const double rmin = std::min(r1, r2);
  if (d <= std::abs(r1 - r2)) return 4.0 / 3.0 * M_PI * rmin * rmin * rmin;
  const double s = r1 + r2 - d;
  return M_PI * s * s * (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) / (12 * d);
}

bool three_spheres_intersect(const Eigen::Vector3d& c1, double r1, const Eigen::Vector3d& c2, double r2,
                             const Eigen::Vector3d& c3, double r3) {
  const Eigen::Vector3d c[3] = {c1, c2, c3};
  const double r[3] = {r1, r2, r3};
  auto f = [&](const Eigen::Vector3d& x) {
    double m = -INFINITY;
    for (int i = 0; i < 3; ++i) m = std::max(m, (x - c[i]).squaredNorm() - r[i] * r[i]);
    return m;
  };
  double best = INFINITY;
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, f(c[i]));
    const int j = (i + 1) % 3;
    const Eigen::Vector3d u = c[j] - c[i];
    const double d2 = u.squaredNorm();
    if (d2 > 0) best = std::min(best, f(c[i] + (d2 + r[i] * r[i] - r[j] * r[j]) / (2 * d2) * u));
  }
  // radical centre: x = c1 + alpha u + beta v with 2 (x - c1).u = |u|^2 + r1^2 - r2^2 and the same for v
  const Eigen::Vector3d u = c2 - c1, v = c3 - c1;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), det = uu * vv - uv * uv;
  if (det > 1e-14 * uu * vv) {
    const double bu = 0.5 * (uu + r1 * r1 - r2 * r2), bv = 0.5 * (vv + r1 * r1 - r3 * r3);
    const double alpha = (bu * vv - bv * uv) / det, beta = (bv * uu - bu * uv) / det;
    best = std::min(best, f(c1 + alpha * u + beta * v));
  }
  return best < 0;
}

namespace {

// Sum of f(e) over the images e = d + (k_x L_x, k_y L_y, k_z L_z) of a separation d (nearest
// image) closer than reach, k = 0 along the axes that are not periodic.
template <class F>
void for_images_within(const Eigen::Vector3d& d, double reach, const Eigen::Vector3d& box, std::array<bool, 3> periodic,
                       F&& f) {
  long lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = periodic[a] ? static_cast<long>(std::ceil((-reach - d[a]) / box[a])) : 0;
    hi[a] = periodic[a] ? static_cast<long>(std::floor((reach - d[a]) / box[a])) : 0;
  }
  for (long kx = lo[0]; kx <= hi[0]; ++kx)
    for (long ky = lo[1]; ky <= hi[1]; ++ky)
      for (long kz = lo[2]; kz <= hi[2]; ++kz) {
        const Eigen::Vector3d e = d + Eigen::Vector3d(kx * box[0], ky * box[1], kz * box[2]);
        if (e.norm() < reach) f(e, kx == 0 && ky == 0 && kz == 0);
      }
}

}  // namespace

SphereVolumes sphere_volumes(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const Eigen::Vector3d& box,
                             std::array<bool, 3> periodic) {
  SphereVolumes v;
  const long n = centres.rows();
  double total = 0, overlap = 0;
  for (long i = 0; i < n; ++i) total += 4.0 / 3.0 * M_PI * std::pow(radii[i], 3);
  // Summed per sphere, then in order: thread-independent.
  std::vector<double> per_sphere(static_cast<std::size_t>(n), 0.0);
  std::vector<long> triples(static_cast<std::size_t>(n), 0), images(static_cast<std::size_t>(n), 0);
#pragma omp parallel
  {
    std::vector<std::pair<long, Eigen::Vector3d>> neighbours;  // overlapping j > i, nearest-image offset
#pragma omp for schedule(dynamic, 16)
    for (long i = 0; i < n; ++i) {
      neighbours.clear();
      const double ri = radii[i];
      // the sphere and its own images: each pair of images once per cell (k and -k alike)
      for_images_within(Eigen::Vector3d::Zero(), 2 * ri, box, periodic, [&](const Eigen::Vector3d& e, bool self) {
        if (self) return;
        per_sphere[i] += 0.5 * lens_volume(ri, ri, e.norm());
        ++images[i];
      });
      images[i] /= 2;
      for (long j = i + 1; j < n; ++j) {
        Eigen::Vector3d d = (centres.row(j) - centres.row(i)).transpose();
        for (int a = 0; a < 3; ++a)
          if (periodic[a]) d[a] = minimum_image(d[a], box[a]);
        const double reach = ri + radii[j];
        int met = 0;
        for_images_within(d, reach, box, periodic, [&](const Eigen::Vector3d& e, bool) {
          per_sphere[i] += lens_volume(ri, radii[j], e.norm());
          ++met;
        });
        if (d.norm() < reach) neighbours.emplace_back(j, d);
        if (met > 1) ++images[i];  // the pair overlaps through more than one image
      }
      for (std::size_t p = 0; p < neighbours.size(); ++p)
        for (std::size_t q = p + 1; q < neighbours.size(); ++q) {
          const auto& [j, dj] = neighbours[p];
          const auto& [k, dk] = neighbours[q];
          if ((dk - dj).norm() < radii[j] + radii[k] &&
              three_spheres_intersect(Eigen::Vector3d::Zero(), ri, dj, radii[j], dk, radii[k]))
            ++triples[i];
        }
    }
  }
  for (double o : per_sphere) overlap += o;
  for (long t : triples) v.triple_overlaps += t;
  for (long t : images) v.image_overlaps += t;
  v.total = total;
  v.pair_overlap = overlap;
  return v;
}

}  // namespace cmp::voxel
