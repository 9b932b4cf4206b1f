// lib/io/sphere_packing_xyz.hpp: the one reader of sphere packings in extended XYZ, its rules
// and the radius column names of OVITO and ASE.
#include "io/sphere_packing_xyz.hpp"

#include "io/input.hpp"
#include "io/xyz_frame.hpp"

#include "io_test_support.hpp"

#include <cstdlib>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {
const std::string kLattice = "Lattice=\"4 0 0 0 4 0 0 0 4\" ";
std::string frame(const std::string& comment, const std::string& rows, int n) {
  return std::to_string(n) + "\n" + comment + "\n" + rows;
}
}  // namespace

TEST_CASE("sphere packing frames give box and pbc and centres and radii and info for every frame", "[sphere_packing_xyz]") {
  TempDir dir;
  const auto path = dir.file("p.xyz");
  write_text(path,
             frame(kLattice + "Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"T T F\" D0=1.5 step=0",
                   "X 1 1 1 0.5\nX 3 3 3 0.7\n", 2) +
                 frame(kLattice + "Properties=species:S:1:pos:R:3:radius:R:1", "X 2 2 2 0.25\n", 1));
  const auto frames = read_sphere_packing_xyz(path, PbcRule::as_in_file);
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].size() == 2);
  CHECK(frames[0].box == Eigen::Vector3d::Constant(4));
  CHECK(frames[0].pbc == std::array<bool, 3>{true, true, false});
  CHECK(frames[0].radii[1] == 0.7);
  CHECK(frames[0].centres(1, 2) == 3.0);
  CHECK(*frames[0].find_info("step") == "0");
  CHECK(frames[0].positive_info("D0") == 1.5);
  CHECK_FALSE(frames[1].positive_info("D0"));
  CHECK(frames[1].line == 5);
  CHECK(frames[1].pbc == std::array<bool, 3>{true, true, true});  // a Lattice without pbc
  // the same file with every axis required periodic
  CHECK(input_error([&] { read_sphere_packing_xyz(path, PbcRule::require_all); }) ==
        path + ":1: pbc is not \"T T T\": a periodic packing is needed");
}

TEST_CASE("sphere packing radius columns of ours and OVITO and ASE", "[sphere_packing_xyz]") {
  TempDir dir;
  const auto path = dir.file("r.xyz");
  for (const std::string name : {"radius", "Radius", "RADIUS", "radii"}) {
    INFO(name);
    write_text(path, frame(kLattice + "Properties=species:S:1:pos:R:3:" + name + ":R:1", "X 1 1 1 0.5\n", 1));
    const auto f = read_sphere_packing_xyz(path, PbcRule::require_all);
    CHECK(f[0].radii[0] == 0.5);
    CHECK(f[0].radius_column == name);
  }
  write_text(path, frame(kLattice + "Properties=species:S:1:pos:R:3:radius:R:2", "X 1 1 1 0.5 0.5\n", 1));
  CHECK_THAT(input_error([&] { read_sphere_packing_xyz(path, PbcRule::as_in_file); }),
             Contains("radius column radius:R:2: expected one real number per atom"));
}

TEST_CASE("sphere packing files written by ASE are read", "[sphere_packing_xyz]") {
  TempDir dir;
  const auto path = dir.file("ase.xyz");
  const std::string script =
      "import sys, numpy as np, ase, ase.io\n"
      "a = ase.Atoms('H2', positions=[[0.5, 0.5, 0.5], [1.5, 1.5, 1.5]], cell=np.diag([3.0, 3.0, 3.5]), pbc=True)\n"
      "a.new_array('radii', np.array([0.4, 0.45]))\n"
      "a.info['D0'] = 0.9\n"
      "b = a.copy(); b.arrays.pop('radii'); b.new_array('radius', np.array([0.3, 0.35]))\n"
      "ase.io.write(sys.argv[1], [a, b], format='extxyz')\n";
  write_text(dir.file("w.py"), script);
  REQUIRE(std::system(("/usr/bin/python3 " + dir.file("w.py") + " " + path).c_str()) == 0);
  const auto f = read_sphere_packing_xyz(path, PbcRule::require_all);
  REQUIRE(f.size() == 2);
  CHECK(f[0].radius_column == "radii");
  CHECK(f[0].radii[1] == 0.45);
  CHECK(f[0].box[2] == 3.5);
  CHECK(f[0].positive_info("D0") == 0.9);
  CHECK(f[1].radius_column == "radius");
  CHECK(f[1].radii[0] == 0.3);
}

TEST_CASE("sphere packing rules give file and line", "[sphere_packing_xyz]") {
  const std::string p = "Properties=species:S:1:pos:R:3:radius:R:1";
  const std::vector<BadInputCase> cases = {
      {"no Lattice", frame(p, "X 1 1 1 1\n", 1), 1, "no Lattice"},
      {"tilted Lattice", frame("Lattice=\"4 0 0 1 4 0 0 0 4\" " + p, "X 1 1 1 1\n", 1), 1, "orthorhombic"},
      {"zero side", frame("Lattice=\"4 0 0 0 0 0 0 0 4\" " + p, "X 1 1 1 1\n", 1), 1, "not positive"},
      {"no radius column", frame(kLattice + "Properties=species:S:1:pos:R:3", "X 1 1 1\n", 1), 1,
       "no radius column"},
      {"negative radius", frame(kLattice + p, "X 1 1 1 1\nX 2 2 2 -1\n", 2), 4, "radius -1 is not a positive number"},
      {"zero radius", frame(kLattice + p, "X 1 1 1 0\n", 1), 3, "radius 0 is not a positive number"},
      {"duplicate", frame(kLattice + p, "X 1 1 1 1\nX 2 2 2 1\nX 1 1 1 1\n", 3), 5, "duplicates another"},
      {"duplicate across the periodic boundary", frame(kLattice + p, "X 0 1 1 1\nX 2 2 2 1\nX 4 1 1 1\n", 3), 5,
       "duplicates another"},
      {"no spheres", frame(kLattice + p, "", 0), 1, "the frame has no spheres"},
      {"no spheres in the second frame", frame(kLattice + p, "X 1 1 1 1\n", 1) + frame(kLattice + p, "", 0), 4,
       "the frame has no spheres"},
  };
  check_bad_inputs(cases, "bad.xyz",
                   [](const std::string& path) { read_sphere_packing_xyz(path, PbcRule::as_in_file); });
}

TEST_CASE("sphere packing duplicates not across a non-periodic boundary and found in O(N)", "[sphere_packing_xyz]") {
  TempDir dir;
  const auto path = dir.file("d.xyz");
  write_text(path, frame(kLattice + "Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"F T T\"",
                         "X 0 1 1 1\nX 4 1 1 1\n", 2));
  CHECK(read_sphere_packing_xyz(path, PbcRule::as_in_file)[0].size() == 2);  // 4 apart along x
  // a simple cubic lattice of 27000 spheres, many sharing each plane: no duplicate found
  const int k = 30;
  std::string rows;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l)
        rows += "X " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(l) + " 0.4\n";
  const auto side = std::to_string(k);
  write_text(path, frame("Lattice=\"" + side + " 0 0 0 " + side + " 0 0 0 " + side +
                             "\" Properties=species:S:1:pos:R:3:radius:R:1",
                         rows, k * k * k));
  CHECK(read_sphere_packing_xyz(path, PbcRule::require_all)[0].size() == k * k * k);
}

TEST_CASE("D0 in the comment line is read strictly", "[sphere_packing_xyz]") {
  TempDir dir;
  const auto path = dir.file("d0.xyz");
  for (const std::string bad : {"2.0abc", "0x2", "nan", "-1", "0"}) {
    INFO(bad);
    write_text(path, frame(kLattice + "Properties=species:S:1:pos:R:3:radius:R:1 D0=" + bad, "X 1 1 1 1\n", 1));
    const auto f = read_sphere_packing_xyz(path, PbcRule::as_in_file);
    CHECK(input_error([&] { f[0].positive_info("D0"); }) ==
          path + ":2: D0='" + bad + "' is not a positive number");
  }
}
