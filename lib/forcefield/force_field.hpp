#pragma once
// A force field: anything with an energy and its gradient over a flat state vector. The shell
// terms (3 coordinates per vertex: shell/energy_term.hpp), the soft spheres (3 per sphere:
// spheres/hertz_spheres.hpp) and the contacts of budding cells (x, y, theta per cell:
// cells2d/contact_field.hpp) are force fields, each kind registered in a style table of its own
// (core/registry.hpp); one finite-difference harness (tests/forcefield) checks every
// registered style of every kind against its energy.
#include <span>
#include <stdexcept>
#include <string>

namespace cmp {

class ForceField {
 public:
  virtual ~ForceField() = default;
  // The name the style is registered under (e.g. "svk", "hertz").
  virtual std::string name() const = 0;
  // How many doubles a state holds.
  virtual std::size_t state_size() const = 0;
  // The energy at x.
  virtual double energy(std::span<const double> x) const = 0;
  // Adds dE/dx into g (not cleared, so fields accumulate).
  virtual void add_gradient(std::span<const double> x, std::span<double> g) const = 0;

 protected:
  // Throws std::invalid_argument unless x and g hold state_size() doubles: a caller's bug.
  void check_sizes(std::span<const double> x) const { check_sizes(x, x); }
  void check_sizes(std::span<const double> x, std::span<const double> g) const {
    const std::size_t n = state_size();
    if (x.size() != n || g.size() != n)
      throw std::invalid_argument(name() + ": a state of " + std::to_string(x.size()) + " doubles (gradient " +
                                  std::to_string(g.size()) + ") for a field of " + std::to_string(n));
  }
};

}  // namespace cmp
