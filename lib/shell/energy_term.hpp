#pragma once
// One energy term of a shell on a triangle mesh (a "style": stretching, bending, pressure).
// The state is a flat vector of vertex positions x = (x0 y0 z0 x1 y1 z1 ...), 3 #V doubles,
// the layout of mesh::VertexMatrix's row-major storage. Faces and rest geometry are fixed when
// the term is built; energy() and add_gradient() then allocate nothing.
#include <span>
#include <stdexcept>
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

 protected:
  // Throws std::invalid_argument unless x (and g) hold 3 vertex_count() doubles: a caller's
  // bug, checked once per call.
  void check_sizes(std::span<const double> x) const { check_sizes(x, x); }
  void check_sizes(std::span<const double> x, std::span<const double> g) const {
    const auto n = static_cast<std::size_t>(3 * vertex_count());
    if (x.size() != n || g.size() != n)
      throw std::invalid_argument(name() + ": state vector of " + std::to_string(x.size()) + " doubles (gradient " +
                                  std::to_string(g.size()) + ") for a mesh of " + std::to_string(vertex_count()) +
                                  " vertices");
  }
};

}  // namespace cmp::shell
