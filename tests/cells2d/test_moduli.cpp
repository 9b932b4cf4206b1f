// Moduli and the packing file: B and G of a packing beyond jamming, the same to the last
// digit after a write and a read, and the reader's refusals.
#include "cells2d/colony.hpp"
#include "cells2d/moduli.hpp"
#include "cells2d/packing_xyz.hpp"
#include "core/errors.hpp"
#include "io/xyz.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace cmp;
using namespace cmp::cells2d;

namespace {
Colony compressed_colony(double box, std::uint64_t seed, double dphi) {
  GrowthParameters p;
  p.box = box;
  Colony c(p, seed);
  c.grow_to_jamming();
  c.grow_beyond(dphi);
  return c;
}
}  // namespace

TEST_CASE("cells2d moduli: B and G of a compressed packing are positive, G below B, P ~ (2/pi) dphi") {
  Colony colony = compressed_colony(5, 4, 0.01);
  const auto cells = canonical_cells(colony.cells(), 5);
  const Moduli m = measure_moduli(cells, 5, contact_law("harmonic"));
  CHECK(m.packing.pressure > 0.2 * 2 / 3.14159 * 0.01);
  CHECK(m.packing.pressure < 2.0 * 2 / 3.14159 * 0.01);
  CHECK(m.bulk > 0);
  CHECK(m.shear > 0);
  CHECK(m.shear < m.bulk);
  // The pressure tensor is symmetric and P is half its trace.
  CHECK(m.packing.pressure_tensor(0, 1) == Approx(m.packing.pressure_tensor(1, 0)).margin(1e-15));
}

TEST_CASE("cells2d packing file: written and read back, the same moduli to the last digit") {
  Colony colony = compressed_colony(4.5, 7, 0.01);
  const auto cells = canonical_cells(colony.cells(), 4.5);
  const Moduli before = measure_moduli(cells, 4.5, contact_law("harmonic"));
  std::ostringstream text;
  io::XyzWriter(text).write(packing_frame(colony.cells(), 4.5, &before.packing, {{"seed", "7"}}));
  const std::string path = "cells2d_roundtrip_test.xyz";
  std::ofstream(path) << text.str();
  const auto packings = read_packings(path);
  std::remove(path.c_str());
  REQUIRE(packings.size() == 1);
  REQUIRE(packings[0].cells.size() == cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    CHECK(packings[0].cells[i].x == cells[i].x);
    CHECK(packings[0].cells[i].theta == cells[i].theta);
    CHECK(packings[0].cells[i].bud == cells[i].bud);
  }
  const Moduli after = measure_moduli(packings[0].cells, packings[0].box, contact_law("harmonic"));
  CHECK(after.bulk == before.bulk);
  CHECK(after.shear == before.shear);
  CHECK(after.packing.pressure == before.packing.pressure);
  CHECK(after.packing.Z == before.packing.Z);
}

TEST_CASE("cells2d packing file: refusals name the line") {
  std::vector<Cell> cells(2);
  cells[0].x = 1, cells[0].y = 1, cells[0].bud = 0.5;
  cells[1].x = 3, cells[1].y = 3, cells[1].bud = 0.2;
  const io::XyzFrame good = packing_frame(cells, 5, nullptr, {});
  std::ostringstream text;
  io::XyzWriter(text).write(good);
  const std::string base = text.str();
  std::vector<std::string> lines;
  std::istringstream in(base);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  const auto read_text = [&](const std::vector<std::string>& ls) {
    const std::string path = "cells2d_refusal_test.xyz";
    std::ofstream out(path);
    for (const auto& l : ls) out << l << "\n";
    out.close();
    try {
      read_packings(path);
    } catch (const InputError& e) {
      std::remove(path.c_str());
      return std::to_string(e.line()) + ": " + e.what();
    }
    std::remove(path.c_str());
    return std::string("accepted");
  };
  CHECK(read_text(lines) == "accepted");
  {  // a lobe missing: the bud row of cell 1 dropped
    auto ls = lines;
    ls.erase(ls.begin() + 5);
    ls[0] = "3";
    CHECK_THAT(read_text(ls), Catch::StartsWith("5: ") && Catch::Contains("no bud row"));
  }
  {  // a cell id three times
    auto ls = lines;
    ls.push_back(lines[2]);
    ls[0] = "5";
    CHECK_THAT(read_text(ls), Catch::StartsWith("7: ") && Catch::Contains("appears again"));
  }
  {  // a bud larger than its mother
    auto ls = lines;
    const auto at = ls[3].find(" 0.25 ");
    REQUIRE(at != std::string::npos);
    ls[3].replace(at, 6, " 0.75 ");
    CHECK_THAT(read_text(ls), Catch::StartsWith("4: ") && Catch::Contains("not larger than its mother"));
  }
  {  // a non-positive box
    auto ls = lines;
    ls[1].replace(ls[1].find("Lattice=\"5 "), 11, "Lattice=\"-5 ");
    CHECK_THAT(read_text(ls), Catch::StartsWith("2: ") && Catch::Contains("positive sides"));
  }
}
