// Hidden test cases driven by tests/interop/io_readers.sh: they write sample files for the
// real readers (ASE, meshio) to check, and read files those programs wrote. They run only when
// asked for by tag, with CMP_INTEROP_DIR naming the folder to use. The sample values are
// formulas the Python side evaluates the same way, so both sides compare exact doubles.
#include "io/off.hpp"
#include "io/vtk.hpp"
#include "io/xyz.hpp"

#include "io_test_support.hpp"

#include <cstdlib>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;

namespace {

std::string interop_dir() {
  const char* dir = std::getenv("CMP_INTEROP_DIR");
  if (!dir || !*dir) FAIL("set CMP_INTEROP_DIR to the folder for the interop files");
  return dir;
}

// An octahedron of "radius" 1/3 around (0.1, 0.1, 0.1) + shift, faces outward.
mesh::TriMesh octahedron(double shift_x) {
  mesh::TriMesh m;
  m.V.resize(6, 3);
  const double d[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) m.V(i, k) = d[i][k] / 3.0 + 0.1 + (k == 0 ? shift_x : 0.0);
  m.F.resize(8, 3);
  m.F << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  return m;
}

}  // namespace

TEST_CASE("write sample files for the interop readers", "[.interop]") {
  const auto dir = interop_dir();

  std::vector<XyzFrame> frames;
  for (int f = 0; f < 3; ++f) {
    const int n = 4 + f;
    XyzFrame fr;
    fr.has_lattice = true;
    fr.lattice << 10.0 / 3.0, 0, 0, 0.1, 5.0 + f, 0, 0, 0, 7.25;
    fr.pbc = {true, false, true};
    std::vector<std::string> species;
    mesh::VertexMatrix V(n, 3);
    Eigen::VectorXd radius(n);
    std::vector<int> shell;
    for (int i = 0; i < n; ++i) {
      species.push_back(i % 2 ? "O" : "H");
      V(i, 0) = i * 0.1 + f;
      V(i, 1) = i / 3.0;
      V(i, 2) = i % 2 ? 1e-8 * (i + 1) : -0.0;
      radius[i] = 0.5 + 1e-8 * i;
      shell.push_back(7 * i - 3 - f);
    }
    fr.set_species(species);
    fr.set_positions(V);
    fr.set_real_column("radius", radius);
    fr.set_integer_column("shell", shell);
    fr.set_info("tool", "cmp-test");
    fr.set_info("step", std::to_string(f));
    fr.set_info("note", "two words");
    frames.push_back(std::move(fr));
  }
  write_xyz(dir + "/frames.xyz", frames);

  const auto m = octahedron(0.0);
  write_off(dir + "/octahedron.off", m.V, m.F, {"cmp test_io interop"});
  const auto m2 = octahedron(2.0);
  mesh::VertexMatrix V(12, 3);
  V << m.V, m2.V;
  mesh::FaceMatrix F(16, 3);
  F << m.F, (m2.F.array() + 6).matrix();
  PackingInfo packing;
  packing.box = Eigen::Vector3d(5.0, 4.0, 3.5);
  packing.periodic = {true, true, false};
  packing.shell_vertex_counts = {6, 6};
  write_off(dir + "/packing.off", V, F, {"two shells"}, &packing);

  VoxelImage<std::uint8_t> u8({7, 5, 3});
  u8.origin = Eigen::Vector3d(0.5, -1.0, 2.0);
  u8.spacing = Eigen::Vector3d(0.25, 0.5, 1.0 / 3.0);
  u8.name = "solid";
  VoxelImage<float> f32({4, 3, 2});
  f32.spacing = Eigen::Vector3d::Constant(0.04);
  f32.name = "pressure";
  VoxelImage<std::int32_t> i32({3, 3, 3});
  i32.name = "label";
  VoxelImage<double> f64({2, 3, 4});
  f64.name = "speed";
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 7; ++x)
        u8(x, y, z) = static_cast<std::uint8_t>((x + 7 * y + 35 * z) * 2 + 1);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) f32(x, y, z) = static_cast<float>(x * 0.5 - y / 3.0 + z * 1e-8);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) i32(x, y, z) = x - 10 * y + 100 * z - 50;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 2; ++x) f64(x, y, z) = x / 3.0 + y * 0.1 + z * 1e-300;
  write_vtk(dir + "/uint8.vtk", u8, "test_io interop uint8");
  write_vtk(dir + "/float.vtk", f32, "test_io interop float");
  write_vtk(dir + "/int32.vtk", i32, "test_io interop int32");
  write_vtk(dir + "/double.vtk", f64, "test_io interop double");
}

TEST_CASE("read an extended XYZ written by ASE", "[.interop-read]") {
  // Written by tests/interop/io_readers.py write_ase: ASE prints positions with %16.8f, so
  // the values are exact in 8 decimals.
  const auto frames = read_xyz(interop_dir() + "/ase_written.xyz");
  REQUIRE(frames.size() == 2);
  for (int k = 0; k < 2; ++k) {
    INFO("frame " << k);
    const auto& f = frames[k];
    REQUIRE(f.size() == 3);
    CHECK(f.species() == std::vector<std::string>{"H", "O", "H"});
    const auto V = f.positions();
    for (int i = 0; i < 3; ++i) {
      CHECK(V(i, 0) == 0.125 * i + k);
      CHECK(V(i, 1) == -1.5 * i);
      CHECK(V(i, 2) == 2.25);
    }
    CHECK(f.has_lattice);
    Eigen::Matrix3d L;
    L << 6, 0, 0, 0, 7, 0, 0.5, 0, 8;
    CHECK(f.lattice == L);
    CHECK(f.pbc == std::array<bool, 3>{true, false, true});
    const auto radius = f.real_column("radius");
    CHECK(radius(1, 0) == 0.75);
    const auto& shell = f.column("shell", 'I', 1);
    CHECK(shell.values == std::vector<double>{1, 2, 3.0 + k});
    REQUIRE(f.find_info("label"));
    CHECK(*f.find_info("label") == "two words");
    CHECK(*f.find_info("step") == std::to_string(k));
  }
}

TEST_CASE("read an OFF written by meshio", "[.interop-read]") {
  const auto off = read_off(interop_dir() + "/meshio_written.off");
  const auto m = octahedron(0.0);
  REQUIRE(off.V.rows() == 6);
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) CHECK(same_bits(off.V(i, k), m.V(i, k)));
  CHECK(off.F == m.F);
  CHECK(off.comments == std::vector<std::string>{"Created by meshio"});
}
