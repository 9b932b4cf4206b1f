#include "shell/wall_load.hpp"

#include "shell/hertz_contacts.hpp"
#include "shell/observables.hpp"

#include <span>

namespace cmp::shell {

std::vector<Plane> box_walls(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) {
  std::vector<Plane> walls;
  for (int a = 0; a < 3; ++a) {
    if (periodic[a]) continue;
    Plane low, high;
    low.point.setZero();
    low.normal = Eigen::Vector3d::Unit(a);
    high.point = lengths[a] * Eigen::Vector3d::Unit(a);
    high.normal = -Eigen::Vector3d::Unit(a);
    walls.push_back(low);
    walls.push_back(high);
  }
  return walls;
}

WallLoad wall_load(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const Eigen::Vector3d& lengths,
                   std::array<bool, 3> periodic, ContactParameters p) {
  WallLoad load;
  p.walls = box_walls(lengths, periodic);
  if (p.walls.empty()) return load;
  load.walls = static_cast<int>(p.walls.size());
  for (int a = 0; a < 3; ++a)
    if (!periodic[a]) load.wall_area += 2 * lengths[(a + 1) % 3] * lengths[(a + 2) % 3];
  const WallContacts contacts(mesh::TriMesh{V, F}, p);
  const std::span<const double> x(V.data(), static_cast<std::size_t>(V.size()));
  for (double f : contacts.wall_forces(x)) load.force += f;
  const Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(V.data(), V.size());
  load.contact_area = contact_area(xv, F, contacts.touching(x));
  return load;
}

}  // namespace cmp::shell
