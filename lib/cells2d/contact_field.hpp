#pragma once
// The contacts of budding cells as a force field (forcefield/force_field.hpp) over the state
// (x, y, theta) of every cell, the cells' buds held as given: what a generic minimiser or the
// finite-difference harness sees. The gradient is minus ContactEngine's forces and torques,
// plus the chamber's walls (chamber_walls.hpp) when a chamber is given.
#include "cells2d/cell.hpp"
#include "cells2d/chamber_walls.hpp"
#include "cells2d/contacts.hpp"

#include "forcefield/force_field.hpp"

#include <memory>
#include <vector>

namespace cmp::cells2d {

class ContactField final : public ForceField {
 public:
  ContactField(std::vector<Cell> cells, const Domain& domain, const ContactLawStyle& law,
               const LawParameters& parameters = {});
  // The cells in a chamber: contacts and walls (the domain is the chamber's, not periodic).
  ContactField(std::vector<Cell> cells, const ChamberGeometry& chamber, const ContactLawStyle& law,
               const LawParameters& parameters = {});
  std::string name() const override { return engine_.law().name; }
  std::size_t state_size() const override { return 3 * cells_.size(); }
  double energy(std::span<const double> x) const override;
  void add_gradient(std::span<const double> x, std::span<double> g) const override;
  // The state of the cells as given: x, y, theta of each.
  std::vector<double> state() const;

 private:
  void place(std::span<const double> x) const;
  mutable std::vector<Cell> cells_;
  mutable ContactEngine engine_;  // its Verlet list follows the states asked for
  std::unique_ptr<ChamberWalls> walls_;
  mutable std::vector<double> force_;
};

}  // namespace cmp::cells2d
