#pragma once
// Fixed external forces on chosen vertices (a dead load: direction and size do not follow the
// deformation): E = -sum_i f_i . x_i. The point and uniform loads of the clamped-plate
// benchmarks (B.5.3, B.5.4) are such loads.
#include "shell/energy_term.hpp"

#include <vector>

namespace cmp::shell {

class DeadLoad final : public EnergyTerm {
 public:
  // forces: 3 #V doubles, the force on every vertex (zero where none acts).
  DeadLoad(long vertex_count, std::vector<double> forces);
  std::string name() const override { return "load"; }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  long vertex_count() const override { return vertex_count_; }
  const std::vector<double>& forces() const { return f_; }
  void set_forces(std::vector<double> forces);

 private:
  long vertex_count_;
  std::vector<double> f_;
};

}  // namespace cmp::shell
