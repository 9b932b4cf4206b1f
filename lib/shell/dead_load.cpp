#include "shell/dead_load.hpp"

#include <cmath>

namespace cmp::shell {

DeadLoad::DeadLoad(long vertex_count, std::vector<double> forces) : vertex_count_(vertex_count) {
  set_forces(std::move(forces));
}

void DeadLoad::set_forces(std::vector<double> forces) {
  check_sizes(forces);
  for (double v : forces)
    if (!std::isfinite(v)) throw std::invalid_argument("load: a force is not finite");
  f_ = std::move(forces);
}

double DeadLoad::energy(std::span<const double> x) const {
  check_sizes(x);
  double e = 0;
  for (std::size_t i = 0; i < f_.size(); ++i) e -= f_[i] * x[i];
  return e;
}

void DeadLoad::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  for (std::size_t i = 0; i < f_.size(); ++i) g[i] -= f_[i];
}

}  // namespace cmp::shell
