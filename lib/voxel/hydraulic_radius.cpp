#include "voxel/hydraulic_radius.hpp"

namespace cmp::voxel {

double ClusterSurface::radius_sites_voxels() const {
  return surface_sites > 0 ? static_cast<double>(volume) / surface_sites : 0.0;
}
double ClusterSurface::radius_faces_voxels() const {
  const long f = total_exposed_faces();
  return f > 0 ? static_cast<double>(volume) / f : 0.0;
}
double ClusterSurface::radius_sites(const VoxelGrid& g) const { return radius_sites_voxels() * g.spacing.mean(); }
double ClusterSurface::radius_faces(const VoxelGrid& g) const {
  const Eigen::Vector3d& h = g.spacing;
  const double area = exposed_faces[0] * h[1] * h[2] + exposed_faces[1] * h[0] * h[2] + exposed_faces[2] * h[0] * h[1];
  return area > 0 ? volume * h.prod() / area : 0.0;
}

ClusterSurface cluster_surface(const std::vector<std::uint8_t>& pore, const std::vector<std::int32_t>& labels,
                               const std::vector<std::uint8_t>& selected, const VoxelGrid& g) {
  const int nx = g.dims[0], ny = g.dims[1], nz = g.dims[2];
  long volume = 0, sites = 0, fx = 0, fy = 0, fz = 0;
  // Is the neighbour at coordinate c (possibly -1 or n) along an axis solid?
  auto solid = [&](int x, int y, int z) { return pore[g.index(x, y, z)] == 0; };
#pragma omp parallel for schedule(static) reduction(+ : volume, sites, fx, fy, fz)
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const std::int32_t l = labels[g.index(x, y, z)];
        if (l == 0 || !selected[l]) continue;
        ++volume;
        int faces[3] = {0, 0, 0};
        for (int s = -1; s <= 1; s += 2) {
          int xx = x + s, yy = y + s, zz = z + s;
          if (xx < 0 || xx >= nx) xx = g.periodic[0] ? (xx + nx) % nx : -1;
          if (yy < 0 || yy >= ny) yy = g.periodic[1] ? (yy + ny) % ny : -1;
          if (zz < 0 || zz >= nz) zz = g.periodic[2] ? (zz + nz) % nz : -1;
          if (xx >= 0 && solid(xx, y, z)) ++faces[0];
          if (yy >= 0 && solid(x, yy, z)) ++faces[1];
          if (zz >= 0 && solid(x, y, zz)) ++faces[2];
        }
        fx += faces[0];
        fy += faces[1];
        fz += faces[2];
        if (faces[0] + faces[1] + faces[2] > 0) ++sites;
      }
  ClusterSurface s;
  s.volume = volume;
  s.surface_sites = sites;
  s.exposed_faces = {fx, fy, fz};
  return s;
}

}  // namespace cmp::voxel
