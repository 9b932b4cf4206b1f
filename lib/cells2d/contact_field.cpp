#include "cells2d/contact_field.hpp"

namespace cmp::cells2d {

ContactField::ContactField(std::vector<Cell> cells, const Domain& domain, const ContactLawStyle& law,
                           const LawParameters& parameters)
    : cells_(std::move(cells)), engine_(domain, law, parameters), force_(3 * cells_.size()) {}

ContactField::ContactField(std::vector<Cell> cells, const ChamberGeometry& chamber, const ContactLawStyle& law,
                           const LawParameters& parameters)
    : ContactField(std::move(cells), chamber.domain(), law, parameters) {
  walls_ = std::make_unique<ChamberWalls>(chamber, law);
}

std::vector<double> ContactField::state() const {
  std::vector<double> x;
  for (const Cell& c : cells_) x.insert(x.end(), {c.x, c.y, c.theta});
  return x;
}

void ContactField::place(std::span<const double> x) const {
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    cells_[i].x = x[3 * i];
    cells_[i].y = x[3 * i + 1];
    cells_[i].theta = x[3 * i + 2];
  }
}

double ContactField::energy(std::span<const double> x) const {
  check_sizes(x);
  place(x);
  return engine_.energy(cells_) + (walls_ ? walls_->energy(cells_) : 0.0);
}

void ContactField::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  place(x);
  engine_.evaluate(cells_, force_.data());
  if (walls_) walls_->add_forces(cells_, force_.data());
  for (std::size_t k = 0; k < g.size(); ++k) g[k] -= force_[k];
}

}  // namespace cmp::cells2d
