#include "lbm/pore_lattice.hpp"

#include "core/errors.hpp"

#include <algorithm>

namespace cmp::lbm {

long PoreLattice::fluid_count() const {
  return static_cast<long>(std::count_if(fluid.begin(), fluid.end(), [](std::uint8_t v) { return v != 0; }));
}

double PoreLattice::porosity() const { return nodes() > 0 ? static_cast<double>(fluid_count()) / nodes() : 0.0; }

PoreLattice open_box(int nx, int ny, int nz) {
  PoreLattice p;
  p.nx = nx;
  p.ny = ny;
  p.nz = nz;
  p.fluid.assign(static_cast<std::size_t>(p.nodes()), 1);
  return p;
}

PoreLattice channel(int length, int width, int axis, int wall_axis, bool duct, int width2) {
  if (axis < 0 || axis > 2 || wall_axis < 0 || wall_axis > 2 || axis == wall_axis || length < 1 || width < 1 ||
      (duct && width2 < 1))
    throw UsageError("channel: bad axes or sizes");
  const int third = 3 - axis - wall_axis;
  int n[3];
  n[axis] = length;
  n[wall_axis] = width + 2;
  n[third] = duct ? width2 + 2 : 1;
  PoreLattice p = open_box(n[0], n[1], n[2]);
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const int c[3] = {x, y, z};
        const bool wall = c[wall_axis] == 0 || c[wall_axis] == n[wall_axis] - 1 ||
                          (duct && (c[third] == 0 || c[third] == n[third] - 1));
        if (wall) p.fluid[static_cast<std::size_t>(p.index(x, y, z))] = 0;
      }
  return p;
}

}  // namespace cmp::lbm
