#pragma once
// One energy term of a shell on a triangle mesh (a "style": stretching, bending, pressure,
// contacts): a force field (forcefield/force_field.hpp) over the vertex positions.
// The state is a flat vector of vertex positions x = (x0 y0 z0 x1 y1 z1 ...), 3 #V doubles,
// the layout of mesh::VertexMatrix's row-major storage. Faces and rest geometry are fixed when
// the term is built; energy() and add_gradient() then allocate nothing.
#include "forcefield/force_field.hpp"

#include <span>
#include <string>

namespace cmp::shell {

class EnergyTerm : public ForceField {
 public:
  // Number of vertices the term was built for (x and g hold 3 times as many doubles).
  virtual long vertex_count() const = 0;
  std::size_t state_size() const final { return static_cast<std::size_t>(3 * vertex_count()); }
};

}  // namespace cmp::shell
