#include "voxel/porosity.hpp"

#include "mesh/enclosed_volume.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::voxel {

double voxel_porosity(const std::vector<std::uint8_t>& pore) {
  if (pore.empty()) return 0;
  long n = 0;
  const long size = static_cast<long>(pore.size());
#pragma omp parallel for reduction(+ : n) schedule(static)
  for (long i = 0; i < size; ++i) n += pore[i] != 0;
  return static_cast<double>(n) / size;
}

std::vector<double> shell_volumes(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets) {
  const int K = static_cast<int>(offsets.size()) - 1;
  if (K <= 0) return {};
  std::vector<std::vector<int>> faces(K);
  for (int f = 0; f < F.rows(); ++f) {
    const int k = static_cast<int>(std::upper_bound(offsets.begin(), offsets.end(), F(f, 0)) - offsets.begin()) - 1;
    faces[std::clamp(k, 0, K - 1)].push_back(f);
  }
  std::vector<double> volumes(K, 0.0);
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < K; ++k) {
    mesh::FaceMatrix Fk(static_cast<long>(faces[k].size()), 3);
    for (std::size_t i = 0; i < faces[k].size(); ++i) Fk.row(static_cast<long>(i)) = F.row(faces[k][i]);
    volumes[k] = mesh::enclosed_volume(V, Fk);
  }
  return volumes;
}

double lens_volume(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0;
  const double rmin = std::min(r1, r2);
  if (d <= std::abs(r1 - r2)) return 4.0 / 3.0 * M_PI * rmin * rmin * rmin;
  const double s = r1 + r2 - d;
  return M_PI * s * s * (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) / (12 * d);
}

SphereVolumes sphere_volumes(const mesh::VertexMatrix& centres, const Eigen::VectorXd& radii, const Eigen::Vector3d& box,
                             std::array<bool, 3> periodic) {
  SphereVolumes v;
  const long n = centres.rows();
  double total = 0, overlap = 0;
  for (long i = 0; i < n; ++i) total += 4.0 / 3.0 * M_PI * std::pow(radii[i], 3);
  std::vector<double> per_sphere(static_cast<std::size_t>(n), 0.0);  // summed in order: thread-independent
#pragma omp parallel for schedule(dynamic, 16)
  for (long i = 0; i < n; ++i)
    for (long j = i + 1; j < n; ++j) {
      Eigen::Vector3d d = (centres.row(j) - centres.row(i)).transpose();
      for (int a = 0; a < 3; ++a)
        if (periodic[a]) d[a] -= box[a] * std::nearbyint(d[a] / box[a]);
      per_sphere[i] += lens_volume(radii[i], radii[j], d.norm());
    }
  for (double o : per_sphere) overlap += o;
  v.total = total;
  v.pair_overlap = overlap;
  return v;
}

}  // namespace cmp::voxel
