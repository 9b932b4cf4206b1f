#pragma once
// One energy term of a shell on a triangle mesh (a "style": stretching, bending, pressure).
// The state is a flat vector of vertex positions x = (x0 y0 z0 x1 y1 z1 ...), 3 #V doubles,
// the layout of mesh::VertexMatrix's row-major storage. Faces and rest geometry are fixed when
// the term is built; energy() and add_gradient() then allocate nothing.
#include <span>
#include <string>

namespace cmp::shell {

class EnergyTerm {
 public:
  virtual ~EnergyTerm() = default;
  // The name the term is registered under (e.g. "svk").
  virtual std::string name() const = 0;
  // The term's energy at positions x (3 #V doubles).
  virtual double energy(std::span<const double> x) const = 0;
  // Adds dE/dx into g (3 #V doubles; g is not cleared, so terms accumulate).
  virtual void add_gradient(std::span<const double> x, std::span<double> g) const = 0;
  // Number of vertices the term was built for (x and g hold 3 times as many doubles).
  virtual long vertex_count() const = 0;
};

}  // namespace cmp::shell
