#include "flowrun/sphere_walls.hpp"

#include "core/minimum_image.hpp"

#include <cmath>
#include <stdexcept>

namespace cmp::flowrun {

SphereWalls::SphereWalls(const Eigen::Vector3d& box, std::array<bool, 3> periodic, const Eigen::MatrixX3d& centres,
                         const Eigen::VectorXd& radii, std::array<int, 3> nodes)
    : box_(box), periodic_(periodic), centres_(centres), radii_(radii), nodes_(nodes) {
  if (!(box.minCoeff() > 0) || !box.allFinite()) throw std::invalid_argument("SphereWalls: box sides must be positive");
  if (centres.rows() != radii.size()) throw std::invalid_argument("SphereWalls: centres and radii differ in size");
  if (radii.size() > 0 && !(radii.minCoeff() > 0)) throw std::invalid_argument("SphereWalls: radii must be positive");
  for (int a = 0; a < 3; ++a) {
    if (nodes[a] < 1) throw std::invalid_argument("SphereWalls: nodes must be at least 1 per axis");
    h_[a] = box[a] / nodes[a];
  }
}

double SphereWalls::minimum_image_if(double d, int axis) const {
  return periodic_[axis] ? minimum_image(d, box_[axis]) : d;
}

std::vector<std::uint8_t> SphereWalls::fluid_mask() const {
  const auto [nx, ny, nz] = nodes_;
  std::vector<std::uint8_t> fluid(static_cast<std::size_t>(nx) * ny * nz, 1);
  for (Eigen::Index s = 0; s < centres_.rows(); ++s) {
    const double r = radii_[s];
    std::array<long, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      // Nodes whose centre (i + 1/2) h can lie within r of the centre.
      lo[a] = static_cast<long>(std::floor((centres_(s, a) - r) / h_[a] - 0.5));
      hi[a] = static_cast<long>(std::ceil((centres_(s, a) + r) / h_[a] - 0.5));
      if (!periodic_[a]) lo[a] = std::max(lo[a], 0L), hi[a] = std::min(hi[a], static_cast<long>(nodes_[a]) - 1);
      else if (hi[a] - lo[a] + 1 > nodes_[a]) lo[a] = 0, hi[a] = nodes_[a] - 1;  // wider than the box
    }
    const double r2 = r * r;
#pragma omp parallel for schedule(static)
    for (long k = lo[2]; k <= hi[2]; ++k) {
      const long zz = ((k % nz) + nz) % nz;
      const double dz = minimum_image_if((k + 0.5) * h_[2] - centres_(s, 2), 2);
      for (long j = lo[1]; j <= hi[1]; ++j) {
        const long yy = ((j % ny) + ny) % ny;
        const double dy = minimum_image_if((j + 0.5) * h_[1] - centres_(s, 1), 1);
        for (long i = lo[0]; i <= hi[0]; ++i) {
          const long xx = ((i % nx) + nx) % nx;
          const double dx = minimum_image_if((i + 0.5) * h_[0] - centres_(s, 0), 0);
          if (dx * dx + dy * dy + dz * dz <= r2) fluid[static_cast<std::size_t>(xx + nx * (yy + ny * zz))] = 0;
        }
      }
    }
  }
  return fluid;
}

double SphereWalls::wall_fraction(int x, int y, int z, const std::array<int, 3>& c) const {
  const Eigen::Vector3d p((x + 0.5) * h_[0], (y + 0.5) * h_[1], (z + 0.5) * h_[2]);
  const Eigen::Vector3d e(c[0] * h_[0], c[1] * h_[1], c[2] * h_[2]);
  const double a = e.squaredNorm();
  double best = 2;
  for (Eigen::Index s = 0; s < centres_.rows(); ++s) {
    Eigen::Vector3d d;
    for (int k = 0; k < 3; ++k) d[k] = minimum_image_if(p[k] - centres_(s, k), k);
    const double r2 = radii_[s] * radii_[s];
    const double cc = d.squaredNorm() - r2;
    if (cc <= 0) return 0.5;  // the node is inside this sphere
    const double b = d.dot(e);
    if (b >= 0) continue;  // moving away from the centre: no entry ahead
    const double disc = b * b - a * cc;
    if (disc < 0) continue;
    const double t = (-b - std::sqrt(disc)) / a;  // first crossing, > 0 since cc > 0
    if (t <= 1 && t < best) best = t;
  }
  return best <= 1 ? best : 0.5;
}

}  // namespace cmp::flowrun
