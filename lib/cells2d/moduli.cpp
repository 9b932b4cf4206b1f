#include "cells2d/moduli.hpp"

#include "cells2d/contacts.hpp"

#include <cmath>

namespace cmp::cells2d {

Moduli measure_moduli(std::vector<Cell> cells, double box, const ContactLawStyle& law, const ModuliParameters& p) {
  Moduli m;
  Domain domain;
  domain.lx = domain.ly = box;
  ContactEngine engine(domain, law);
  const auto count = [&](const RelaxResult& r) {
    m.iterations += r.iterations;
    m.relaxed = m.relaxed && r.converged;
  };
  count(relax(cells, engine, p.relax));
  m.packing = analyse_packing(cells, engine);
  const double phi = m.packing.area_fraction, P = m.packing.pressure;

  // Bulk modulus: a box of area fraction phi + dphi, centres scaled with it.
  {
    const double scale = std::sqrt(phi / (phi + p.dphi));
    std::vector<Cell> squeezed = cells;
    for (Cell& c : squeezed) c.x *= scale, c.y *= scale;
    Domain small = domain;
    small.lx = small.ly = box * scale;
    ContactEngine e(small, law);
    count(relax(squeezed, e, p.relax));
    const PackingAnalysis a = analyse_packing(squeezed, e);
    m.bulk = phi * (a.pressure - P) / (a.area_fraction - phi);
  }
  // Shear modulus: affine simple shear, Lees-Edwards images, relaxed.
  {
    std::vector<Cell> sheared = cells;
    for (Cell& c : sheared) c.x += p.strain * c.y;
    ContactEngine e(domain, law);
    e.set_shear(p.strain);
    count(relax(sheared, e, p.relax));
    const PackingAnalysis a = analyse_packing(sheared, e);
    m.shear = -(a.pressure_tensor(0, 1) - m.packing.pressure_tensor(0, 1)) / p.strain;
  }
  return m;
}

}  // namespace cmp::cells2d
