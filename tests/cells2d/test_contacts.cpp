// The geometry of budding cells and their contacts across the periodic boundary. (Forces and
// torques against the energy, for every registered law: the force-field harness, tests/forcefield.)
#include "cells2d/cell.hpp"
#include "cells2d/contacts.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace cmp;
using namespace cmp::cells2d;

TEST_CASE("cells2d geometry: tangent lobes, centre of mass, the thesis's I/M") {
  Cell c;
  c.x = 1, c.y = 2, c.theta = 0.3, c.bud = 0.6;
  const Eigen::Vector2d m = lobe_centre(c, 0), b = lobe_centre(c, 1);
  CHECK((m - b).norm() == Approx(0.5 * (1 + 0.6)));                         // tangent
  const Eigen::Vector2d com = (m * 1.0 + b * 0.36) / 1.36;                   // mass ~ area
  CHECK((com - Eigen::Vector2d(1, 2)).norm() < 1e-14);
  CHECK(std::atan2(m[1] - b[1], m[0] - b[0]) == Approx(0.3));               // theta: bud -> mother
  // I/M of two disks about the centre of mass, by the parallel-axis theorem.
  const double w1 = 1 / 1.36, w2 = 0.36 / 1.36;
  const double direct = w1 * (1.0 / 8 + (m - com).squaredNorm()) + w2 * (0.36 / 8 + (b - com).squaredNorm());
  CHECK(inertia_per_mass(0.6) == Approx(direct).epsilon(1e-13));
  CHECK(inertia_per_mass(0) == Approx(1.0 / 8));
  const Cell back = cell_from_lobes(m, b, 0.6);
  CHECK(back.x == Approx(1).epsilon(1e-14));
  CHECK(back.y == Approx(2).epsilon(1e-14));
  CHECK(back.theta == Approx(0.3).epsilon(1e-14));
  CHECK(cell_area(bud_for_area(cell_area(0.37))) == Approx(cell_area(0.37)).epsilon(1e-15));
}

TEST_CASE("cells2d harness: contacts across the periodic boundary are found and counted once") {
  for (const ContactLawStyle& law : contact_laws()) {
    Domain box;
    box.lx = box.ly = 4;
    ContactEngine engine(box, law);
    // Two bud-less cells overlapping by 0.1 across x = 0, and the same pair inside the box.
    std::vector<Cell> across(2), inside(2);
    across[0].x = 0.05, across[1].x = 3.95 - 0.8, across[0].y = across[1].y = 2;
    inside[0].x = 2.05, inside[1].x = 1.95 - 0.8, inside[0].y = inside[1].y = 2;
    // Buds of zero size sit on the mother's rim, turned away from the contact.
    across[0].theta = inside[0].theta = std::numbers::pi;
    const double ea = engine.energy(across), ei = engine.energy(inside);
    CHECK(ea > 0);
    CHECK(ea == Approx(ei).epsilon(1e-12));
    CHECK(ea == Approx(law.energy(0.1, {})).epsilon(1e-9));
    int n = 0;
    engine.for_each_contact(across, [&](const Contact& c) {
      ++n;
      CHECK(c.overlap == Approx(0.1));
    });
    CHECK(n == 1);
  }
}

TEST_CASE("cells2d: unknown contact law is refused naming the choices") {
  CHECK_THROWS_WITH(contact_law("lennard-jones"), Catch::Contains("harmonic"));
}
