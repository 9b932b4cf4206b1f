#include "packing/packing_file.hpp"

#include "core/errors.hpp"
#include "spheremesh/subdivision.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

using namespace cmp::packing;

namespace {
std::string write_file(const std::string& name, const std::string& text) {
  const auto path = (std::filesystem::temp_directory_path() / ("cmp_packing_" + name)).string();
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("read_packing: spheres from extended XYZ, scaled, D0 from the radii or the file", "[packing]") {
  const auto p = write_file("a.xyz",
                            "2\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1:contacts:I:1 "
                            "pbc=\"T T T\"\nX 1 1 1 0.5 0\nX 3 3 3 0.7 0\n");
  const auto s = read_packing(p, {1.1, 0});
  CHECK(s.kind == Packing::Kind::Spheres);
  CHECK(s.particles() == 2);
  CHECK(s.radii[1] == Approx(0.77));
  CHECK(s.d0 == Approx(1.2));
  CHECK(s.d0_source == "mean_diameter");
  CHECK(s.box == Eigen::Vector3d::Constant(4));
  const auto withd0 = write_file("b.xyz",
                                 "1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1 D0=2\n"
                                 "X 1 1 1 0.5\n");
  CHECK(read_packing(withd0).d0 == 2);
  CHECK(read_packing(withd0).d0_source == "file");
  CHECK(read_packing(withd0, {1, 3}).d0_source == "option");
  const auto noradius = write_file("c.xyz", "1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3\nX 1 1 1\n");
  CHECK_THROWS_AS(read_packing(noradius), cmp::InputError);
  CHECK_THROWS_WITH(read_packing(noradius), Catch::Contains("radius"));
  const auto nolattice = write_file("d.xyz", "1\nProperties=species:S:1:pos:R:3:radius:R:1\nX 1 1 1 1\n");
  CHECK_THROWS_WITH(read_packing(nolattice), Catch::Contains("Lattice"));
}

TEST_CASE("read_packing: shells from a packing OFF are unwrapped, and no box is an error", "[packing]") {
  // One octahedron of radius 0.5 centred on the corner of a periodic box of side 2: its
  // vertices wrapped into the box.
  std::string off = "OFF\n# box 2 2 2\n# periodic 1 1 1\n# shells 1 6\n6 8 0\n";
  off += "0.5 0 0\n1.5 0 0\n0 0.5 0\n0 1.5 0\n0 0 0.5\n0 0 1.5\n";
  off += "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  const auto p = read_packing(write_file("oct.off", off));
  CHECK(p.kind == Packing::Kind::Shells);
  CHECK(p.particles() == 1);
  CHECK((p.V.colwise().maxCoeff() - p.V.colwise().minCoeff()).maxCoeff() == Approx(1.0));  // unwrapped
  // D0 from the volume: the octahedron's volume 4/3 r^3 = 1/6 -> D0 = (6 V / pi)^(1/3)
  CHECK(p.d0 == Approx(std::cbrt(1.0 / M_PI)));
  CHECK(p.d0_source == "shell_volume");
  std::string nobox = off;
  nobox.erase(nobox.find("# box 2 2 2\n"), 12);
  CHECK_THROWS_WITH(read_packing(write_file("nobox.off", nobox)), Catch::Contains("box"));
  std::string badcount = off;
  badcount.replace(badcount.find("# shells 1 6"), 12, "# shells 2 3 4");
  CHECK_THROWS_AS(read_packing(write_file("count.off", badcount)), cmp::InputError);
}

namespace {
const std::string kOct = [] {
  std::string off = "OFF\n# box 2 2 2\n# periodic 1 1 1\n# shells 1 6\n6 8 0\n";
  off += "0.5 0 0\n1.5 0 0\n0 0.5 0\n0 1.5 0\n0 0 0.5\n0 0 1.5\n";
  off += "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  return off;
}();
const std::string kTwoFrames =
    "1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"T T F\"\nX 1 1 1 0.5\n"
    "2\nLattice=\"5 0 0 0 5 0 0 0 5\" Properties=species:S:1:pos:R:3:Radius:R:1\nX 1 1 1 0.5\nX 3 3 3 0.5\n";

// Replaces std::cin's buffer for the lifetime of the object.
struct Stdin {
  explicit Stdin(const std::string& text) : buf(text), old(std::cin.rdbuf(buf.rdbuf())) {}
  ~Stdin() {
    std::cin.rdbuf(old);
    std::cin.clear();
  }
  std::istringstream buf;
  std::streambuf* old;
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const cmp::InputError& e) {
    return e.what();
  }
  return "no InputError";
}
}  // namespace

TEST_CASE("read_packings gives one packing per XYZ frame with the pbc of the file", "[packing]") {
  const auto path = write_file("frames.xyz", kTwoFrames);
  const auto p = read_packings(path, {2, 0});
  REQUIRE(p.size() == 2);
  CHECK(p[0].periodic == std::array<bool, 3>{true, true, false});
  CHECK(p[0].particles() == 1);
  CHECK(p[1].particles() == 2);
  CHECK(p[1].box == Eigen::Vector3d::Constant(5));
  CHECK(p[1].radii[1] == 1.0);  // scaled by 2
  CHECK(p[1].d0 == 1.0);        // unscaled mean diameter
  CHECK(read_packing(path).particles() == 2);  // the last frame
  CHECK(read_packings(write_file("oct1.off", kOct)).size() == 1);
}

TEST_CASE("read_packings tells the format from the content and a dash holds either", "[packing]") {
  CHECK(read_packings(write_file("spheres.dat", kTwoFrames)).size() == 2);  // no .xyz name needed
  CHECK(read_packings(write_file("shells.txt", kOct))[0].kind == Packing::Kind::Shells);
  {
    Stdin in(kTwoFrames);
    const auto p = read_packings("-");
    REQUIRE(p.size() == 2);
    CHECK(p[0].file == "-");
    CHECK(p[1].kind == Packing::Kind::Spheres);
  }
  {
    Stdin in(kOct);
    CHECK(read_packing("-").kind == Packing::Kind::Shells);
  }
  {
    Stdin in("a,b\n1,2\n");
    CHECK(error_of([] { read_packings("-"); }) ==
          "<stdin>:1: expected a packing: an OFF ('OFF' first) or an extended XYZ (an atom count "
          "first), the content is CSV");
  }
  const auto ply = write_file("ply.off", "# c\nply\nformat ascii 1.0\n");
  CHECK(error_of([&] { read_packings(ply); }) ==
        ply + ":2: expected a packing: an OFF ('OFF' first) or an extended XYZ (an atom count first), got 'ply'");
  CHECK(error_of([] { read_packings(write_file("empty.off", "\n# nothing\n")); }) ==
        write_file("empty.off", "\n# nothing\n") + ": empty file: expected a packing: an OFF ('OFF' first) or "
                                                 "an extended XYZ (an atom count first)");
}

TEST_CASE("read_packings reads D0 strictly and reports it at its line", "[packing]") {
  std::string off = kOct;
  off.insert(off.find("6 8 0"), "# D0=2.0abc\n");
  const auto bad_off = write_file("d0.off", off);
  CHECK(error_of([&] { read_packings(bad_off); }) == bad_off + ":5: D0='2.0abc' is not a positive number");
  std::string good = kOct;
  good.insert(good.find("6 8 0"), "# D0=2.5\n");
  CHECK(read_packing(write_file("d0good.off", good)).d0 == 2.5);
  const auto hex = write_file("d0.xyz", "1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1 "
                                        "D0=0x2\nX 1 1 1 0.5\n");
  CHECK(error_of([&] { read_packings(hex); }) == hex + ":2: D0='0x2' is not a positive number");
}

TEST_CASE("read_packings refuses duplicated particles and empty frames", "[packing]") {
  const auto dup = write_file("dup.xyz", "2\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1\n"
                                         "X 1 1 1 0.5\nX 1 1 1 0.5\n");
  CHECK_THAT(error_of([&] { read_packings(dup); }), Catch::StartsWith(dup + ":4: particle duplicates"));
  const auto empty = write_file("empty.xyz", "0\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3:radius:R:1\n");
  CHECK(error_of([&] { read_packings(empty); }) == empty + ":1: the frame has no spheres");
}
