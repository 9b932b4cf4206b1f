#include "voxel/hydraulic_radius.hpp"

#include "voxel/label_components.hpp"
#include "voxel/percolation.hpp"

#include <catch2/catch.hpp>

using namespace cmp::voxel;

namespace {
ClusterSurface spanning_surface(const std::vector<std::uint8_t>& pore, const VoxelGrid& g, int axis) {
  std::vector<std::int32_t> labels;
  const int n = label_components(pore.data(), g.dims, labels);
  const auto flags = label_face_flags(labels, g.dims, n);
  return cluster_surface(pore, labels, spanning_labels(flags, axis), g);
}
}  // namespace

TEST_CASE("hydraulic radius of a straight square channel", "[voxel][hydraulic]") {
  // A w x w channel along x through solid, in a box periodic along x: R_h = area / perimeter
  // = w / 4 in voxels with exposed faces; surface sites count w^2 - (w-2)^2 per slice.
  const int n = 20, w = 6;
  const auto g = make_grid(Eigen::Vector3d(n * 0.1, n * 0.1, n * 0.1), 0.1);
  std::vector<std::uint8_t> pore(g.size(), 0);
  for (int z = 7; z < 7 + w; ++z)
    for (int y = 5; y < 5 + w; ++y)
      for (int x = 0; x < n; ++x) pore[g.index(x, y, z)] = 1;
  const auto s = spanning_surface(pore, g, 0);
  CHECK(s.volume == n * w * w);
  CHECK(s.total_exposed_faces() == n * 4 * w);
  CHECK(s.exposed_faces[0] == 0);  // periodic x: the channel continues
  CHECK(s.radius_faces_voxels() == Approx(w / 4.0));
  CHECK(s.surface_sites == n * (w * w - (w - 2) * (w - 2)));
  CHECK(s.radius_sites_voxels() == Approx(36.0 / 20.0));
  CHECK(s.radius_faces(g) == Approx(0.1 * w / 4.0));
  CHECK(s.radius_sites(g) == Approx(0.1 * 36.0 / 20.0));
  // Nothing spans y or z.
  CHECK(spanning_surface(pore, g, 1).volume == 0);
}

TEST_CASE("hydraulic radius of a slab between two plates", "[voxel][hydraulic]") {
  // Gap of w voxels between plates normal to z, periodic in x and y: R_h = gap / 2.
  const int n = 16, w = 5;
  const auto g = make_grid(Eigen::Vector3d::Constant(n * 0.25), 0.25);
  std::vector<std::uint8_t> pore(g.size(), 0);
  for (int z = 4; z < 4 + w; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) pore[g.index(x, y, z)] = 1;
  for (int axis : {0, 1}) {
    const auto s = spanning_surface(pore, g, axis);
    CHECK(s.volume == n * n * w);
    CHECK(s.exposed_faces[2] == 2 * n * n);
    CHECK(s.radius_faces_voxels() == Approx(w / 2.0));
    CHECK(s.radius_sites_voxels() == Approx(w / 2.0));
    CHECK(s.radius_faces(g) == Approx(0.25 * w / 2.0));
  }
  // Non-periodic box: the faces at the box ends are no walls, nothing changes here; but
  // without periodic z the plates at z = 0 and n-1... are solid inside the box anyway.
  auto h = g;
  h.periodic = {false, false, false};
  std::vector<std::int32_t> labels;
  const int nl = label_components(pore.data(), h.dims, labels);
  const auto s = cluster_surface(pore, labels, spanning_labels(label_face_flags(labels, h.dims, nl), 0), h);
  CHECK(s.radius_faces_voxels() == Approx(w / 2.0));
}
