// lib/io/off.hpp: OFF meshes and packings, round trips and every malformed case.
#include "io/off.hpp"

#include "io/input.hpp"
#include "io_test_support.hpp"

#include <cmath>

#include <sstream>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// Two tetrahedra, one per shell, with coordinates no short decimal form holds (those the
// reader takes: magnitudes up to kMaxCoordinate).
mesh::TriMesh two_tetrahedra() {
  std::vector<double> a;
  for (double x : awkward_doubles())
    if (std::abs(x) <= kMaxCoordinate) a.push_back(x);
  mesh::TriMesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) m.V(i, k) = a[(3 * i + k) % a.size()] * (i % 2 ? -1 : 1);
  m.F.resize(8, 3);
  m.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2, 4, 6, 5, 4, 5, 7, 5, 6, 7, 4, 7, 6;
  return m;
}

void require_same_bits(const mesh::VertexMatrix& A, const mesh::VertexMatrix& B) {
  REQUIRE(A.rows() == B.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      INFO("vertex " << i << " coordinate " << k << ": " << A(i, k) << " vs " << B(i, k));
      REQUIRE(same_bits(A(i, k), B(i, k)));
    }
}

const std::string kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

}  // namespace

TEST_CASE("OFF round trip keeps every double, comments and packing lines", "[off]") {
  TempDir dir;
  const auto m = two_tetrahedra();
  PackingInfo packing;
  packing.box = Eigen::Vector3d(10.0 / 3.0, 0.1, 1e-8);
  packing.periodic = {true, false, true};
  packing.shell_vertex_counts = {4, 4};
  const std::vector<std::string> comments = {"rndmesh 0.1 -n 4", "second comment"};
  write_off(dir.file("p.off"), m.V, m.F, comments, &packing);

  const auto off = read_off(dir.file("p.off"));
  require_same_bits(off.V, m.V);
  CHECK(off.F == m.F);
  CHECK(off.comments == comments);
  REQUIRE(off.packing.box);
  for (int k = 0; k < 3; ++k) CHECK(same_bits((*off.packing.box)[k], (*packing.box)[k]));
  CHECK(off.packing.periodic == packing.periodic);
  CHECK(off.packing.shell_vertex_counts == packing.shell_vertex_counts);
  CHECK(shell_vertex_offsets(off.packing) == std::vector<int>{0, 4, 8});
  CHECK(dir.entries() == std::vector<std::string>{"p.off"});
}

TEST_CASE("OFF coordinates and box sides beyond 1e100 are refused at their line", "[off]") {
  // Volumes and distances made from larger numbers overflow (issue 37: a vertex at 1e308
  // crashed shellpack analyze's g(r), a box of 1e308 CGAL's periodic Voronoi).
  std::istringstream far("OFF\n3 1 0\n0 0 0\n1e308 0 0\n0 1 0\n3 0 1 2\n");
  Input far_in("far.off", far);
  CHECK_THROWS_WITH(read_off(far_in), Contains("far.off:4: coordinate '1e308' is beyond +-1e+100"));
  std::istringstream box("OFF\n# box 1 1e101 1\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  Input box_in("box.off", box);
  CHECK_THROWS_WITH(read_off(box_in), Contains("box.off:2: box side '1e101' is beyond 1e+100"));
  std::istringstream edge("OFF\n# box 1 1e100 1\n3 1 0\n0 0 0\n-1e100 0 0\n0 1 0\n3 0 1 2\n");
  Input edge_in("edge.off", edge);
  CHECK(read_off(edge_in).V(1, 0) == -1e100);
}

TEST_CASE("OFF without packing reads back as a plain mesh", "[off]") {
  TempDir dir;
  const auto m = two_tetrahedra();
  write_off(dir.file("m.off"), m.V, m.F);
  const auto text = read_text(dir.file("m.off"));
  CHECK_THAT(text, StartsWith("OFF\n8 8 0\n"));
  const auto off = read_off(dir.file("m.off"));
  require_same_bits(off.V, m.V);
  CHECK(off.F == m.F);
  CHECK(off.comments.empty());
  CHECK_FALSE(off.packing.box);
  CHECK(off.packing.shell_vertex_counts.empty());
  CHECK(shell_vertex_offsets(off.packing).empty());
}

TEST_CASE("OFF stream and file writers give the same bytes", "[off]") {
  TempDir dir;
  const auto m = two_tetrahedra();
  std::ostringstream s;
  write_off(s, m.V, m.F, {"c"});
  write_off(dir.file("m.off"), m.V, m.F, {"c"});
  CHECK(s.str() == read_text(dir.file("m.off")));
  CHECK_THAT(s.str(), Contains("\n-0 ") || Contains(" -0 ") || Contains(" -0\n"));
}

TEST_CASE("OFF reader accepts the forms other programs write", "[off]") {
  TempDir dir;
  SECTION("counts on the OFF line, comments and blank lines between records, CRLF") {
    write_text(dir.file("a.off"),
               "# made by hand\r\nOFF 3 1 0\r\n\r\n# vertices\r\n0 0 0 # origin\r\n1 0 0\r\n\r\n"
               "0 1 0\r\n# faces\r\n3 0 1 2\r\n\r\n# end\r\n");
    const auto off = read_off(dir.file("a.off"));
    CHECK(off.V.rows() == 3);
    CHECK(off.V(1, 0) == 1.0);
    CHECK(off.F(0, 2) == 2);
    CHECK(off.comments == std::vector<std::string>{"made by hand", "vertices", "faces", "end"});
  }
  SECTION("a leading plus sign and exponents") {
    write_text(dir.file("b.off"), "OFF\n3 1 0\n+1 1e-8 -2.5E+3\n1 0 0\n0 1 0\n3 0 1 2\n");
    const auto off = read_off(dir.file("b.off"));
    CHECK(off.V(0, 0) == 1.0);
    CHECK(off.V(0, 1) == 1e-8);
    CHECK(off.V(0, 2) == -2500.0);
  }
  SECTION("no final line break, a comment after OFF") {
    write_text(dir.file("d.off"),
               "OFF # Geomview allows comments here\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
    const auto off = read_off(dir.file("d.off"));
    CHECK(off.F(0, 1) == 1);
  }
  SECTION("an empty mesh") {
    write_text(dir.file("c.off"), "OFF\n0 0 0\n");
    const auto off = read_off(dir.file("c.off"));
    CHECK(off.V.rows() == 0);
    CHECK(off.F.rows() == 0);
  }
  SECTION("the fixture of tests/data/io") {
    const auto off = read_off(CMP_SOURCE_DIR "/tests/data/io/octahedron_packing.off");
    CHECK(off.V.rows() == 12);
    CHECK(off.F.rows() == 16);
    CHECK(off.packing.shell_vertex_counts == std::vector<int>{6, 6});
    CHECK(off.packing.periodic == std::array<bool, 3>{true, true, false});
    CHECK((*off.packing.box)[2] == 4.5);
  }
}

TEST_CASE("OFF dialects of MeshLab and Geomview are read with their extras dropped", "[off]") {
  TempDir dir;
  const std::string V = "0 0 0\n1 0 0\n0 1 0\n";
  const auto read = [&](const std::string& text) {
    write_text(dir.file("d.off"), text);
    const auto off = read_off(dir.file("d.off"));
    REQUIRE(off.V.rows() == 3);
    REQUIRE(off.F.rows() == 1);
    CHECK(off.V(1, 0) == 1.0);
    CHECK(off.F(0, 2) == 2);
  };
  SECTION("per-face colours as MeshLab writes them: integers 0-255, with or without alpha") {
    read("OFF\n3 1 0\n" + V + "3 0 1 2 255 0 0\n");
    read("OFF\n3 1 0\n" + V + "3 0 1 2 255 128 0 255\n");
  }
  SECTION("per-face colours as floats") { read("OFF\n3 1 0\n" + V + "3 0 1 2 0.5 0.25 1 0.75\n"); }
  SECTION("per-vertex colours: COFF, x y z r g b a (MeshLab) or r g b") {
    read("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
    read("COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2\n");
  }
  SECTION("normals (NOFF), normals and colours (CNOFF), texture coordinates (STOFF)") {
    read("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
    read("CNOFF\n3 1 0\n0 0 0 0 0 1 9 9 9 9\n1 0 0 0 0 1 9 9 9 9\n0 1 0 0 0 1 9 9 9\n3 0 1 2 1 2 3\n");
    read("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n");
  }
  SECTION("a COFF written by MeshLab with per-face colours and a header comment") {
    read("COFF\n# Created by MeshLab\n3 1 0\n0 0 0 10 20 30 255\n1 0 0 10 20 30 255\n"
         "0 1 0 10 20 30 255\n3 0 1 2 200 100 50 255\n");
  }
}

TEST_CASE("OFF comments keep their line numbers", "[off]") {
  TempDir dir;
  write_text(dir.file("c.off"), "OFF\n# first\n\n# D0=2\n3 1 0\n# among the vertices\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const auto off = read_off(dir.file("c.off"));
  CHECK(off.comments == std::vector<std::string>{"first", "D0=2", "among the vertices"});
  CHECK(off.comment_lines == std::vector<long>{2, 4, 6});
}

TEST_CASE("OFF reads standard input and writes standard output for '-'", "[off]") {
  {
    StdinFrom in(kTriangle);
    const auto off = read_off("-");
    CHECK(off.V.rows() == 3);
    CHECK(off.F.rows() == 1);
  }
  StdoutTo out;
  mesh::VertexMatrix V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh::FaceMatrix F(1, 3);
  F << 0, 1, 2;
  write_off("-", V, F);
  CHECK(out.text() == kTriangle);
}

TEST_CASE("OFF errors name the file and the line", "[off]") {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string pack = "OFF\n# shells 2 3 3\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 0\n2 1 0\n";
  const std::vector<BadInputCase> cases = {
      {"empty file", "", 0, "empty file"},
      {"only blank lines", "\n  \n\n", 0, "empty file"},
      {"not OFF", "PLY\n", 1, "expected 'OFF' on the first line, got 'PLY'"},
      {"four-dimensional OFF", "4OFF\n3 1 0\n", 1, "unsupported OFF variant '4OFF'"},
      {"binary OFF", "OFF BINARY\n", 1, "binary OFF ('OFF BINARY') is not supported"},
      {"COFF vertex without its colour", "COFF\n3 1 0\n0 0 0\n", 3,
       "expected a vertex 'x y z r g b [a]', got 3 fields"},
      {"face colour not a number", head + "3 0 1 2 255 0 x\n", 6,
       "expected a colour component, got 'x'"},
      {"face with two extra fields", head + "3 0 1 2 1 1\n", 6, "got 6 fields"},
      {"shell counts summed past 2^31 (issue 15)",
       "OFF\n# box 2 2 2\n# periodic 1 1 1\n# shells 3 2147483647 2147483647 5\n3 1 0\n0 0 0\n"
       "1 0 0\n0 1 0\n3 0 1 2\n",
       4, "'# shells' vertex counts add up to 4294967299, but the file has 3 vertices"},
      {"shell counts of two billion each", "OFF\n# shells 2 2000000000 2000000000\n3 1 0\n", 2,
       "add up to 4000000000, but the file has 3 vertices"},
      {"a shell count past int", "OFF\n# shells 1 2147483648\n", 2,
       "expected a shell vertex count in [-9223372036854775808, 2147483647]"},
      {"counts the file cannot hold", "OFF\n2000000000 1 0\n0 0 0\n", 2,
       "the counts line claims 2000000000 vertices and 1 faces, at least 12000000008 bytes"},
      {"no counts line", "OFF\n# c\n", 2, "unexpected end of file: expected the counts line"},
      {"two counts", "OFF\n3 1\n", 2, "expected the counts 'nV nF nE', got 2 fields"},
      {"negative count", "OFF\n-3 1 0\n", 2,
       "expected the vertex count in [0, 2147483647], got '-3'"},
      {"count not a number", "OFF\nthree 1 0\n", 2, "expected the vertex count"},
      {"negative faces on the OFF line", "OFF 3 -1 0\n", 1, "expected the face count"},
      {"non-number", "OFF\n3 1 0\n0 0 0\n1 abc 0\n", 4, "expected a coordinate, got 'abc'"},
      {"trailing junk", "OFF\n3 1 0\n0 0 0\n1 2x 0\n", 4, "expected a coordinate, got '2x'"},
      {"NaN", "OFF\n3 1 0\nnan 0 0\n", 3, "expected a coordinate (finite), got 'nan'"},
      {"Inf", "OFF\n3 1 0\n0 -inf 0\n", 3, "(finite), got '-inf'"},
      {"overflow", "OFF\n3 1 0\n0 0 1e999\n", 3, "(in floating-point range), got '1e999'"},
      {"extra token on a vertex", "OFF\n3 1 0\n0 0 0 1\n", 3,
       "expected a vertex 'x y z', got 4 fields"},
      {"two tokens on a vertex", "OFF\n3 1 0\n0 0\n", 3, "got 2 fields"},
      {"truncated vertices", "OFF\n3 1 0\n0 0 0\n1 0 0\n", 4,
       "unexpected end of file: expected 3 vertices, got 2"},
      {"truncated faces", head, 5, "unexpected end of file: expected 1 faces, got 0"},
      {"quad", head + "4 0 1 2 0\n", 6, "face with 4 vertices: triangles are required"},
      {"index out of range", head + "3 0 1 3\n", 6, "expected a vertex index in [0, 2], got '3'"},
      {"negative index", head + "3 0 -1 2\n", 6, "expected a vertex index in [0, 2], got '-1'"},
      {"extra token on a face", head + "3 0 1 2 255\n", 6,
       "expected a face '3 i j k' or '3 i j k r g b [a]', got 5 fields"},
      {"missing index", head + "3 0 1\n", 6, "got 3 fields"},
      {"more records than announced", head + "3 0 1 2\n3 0 2 1\n", 7,
       "more records than announced"},
      {"box side zero", "OFF\n# box 1 0 1\n", 2, "box side '0' is not positive"},
      {"box of two sides", "OFF\n# box 1 1\n", 2, "expected '# box Lx Ly Lz'"},
      {"box NaN", "OFF\n# box 1 nan 1\n", 2, "expected a box side (finite), got 'nan'"},
      {"two box lines", "OFF\n# box 1 1 1\n# box 2 2 2\n", 3,
       "second '# box' line (the first is line 2)"},
      {"periodic flag 2", "OFF\n# periodic 1 2 0\n", 2, "expected a periodic flag 0 or 1, got '2'"},
      {"periodic of two flags", "OFF\n# periodic 1 1\n", 2, "expected '# periodic x y z'"},
      {"shells counts missing", "OFF\n# shells 2 3\n", 2,
       "announces 2 vertex counts, the line has 1"},
      {"shells K zero", "OFF\n# shells 0\n", 2, "the shell count K must be positive"},
      {"shell count zero", "OFF\n# shells 2 0 3\n", 2,
       "shell vertex count must be positive, got '0'"},
      {"shells not adding up", "OFF\n# shells 2 1 1\n3 1 0\n", 2,
       "'# shells' vertex counts add up to 2, but the file has 3 vertices"},
      {"face across shells", pack + "3 0 1 2\n3 0 4 5\n", 11,
       "face 0 4 5 uses vertices of shells 1, 2 and 2"},
      {"packing line after the counts", "OFF\n3 1 0\n0 0 0\n# box 1 1 1\n", 4,
       "packing line '# box' must come before the counts line"},
  };
  check_bad_inputs(cases, "bad.off", [](const std::string& path) { read_off(path); });
}

TEST_CASE("OFF reader reports unreadable files", "[off]") {
  TempDir dir;
  const auto missing = dir.file("missing.off");
  CHECK(input_error([&] { read_off(missing); }) ==
        missing + ": cannot open: No such file or directory");
  CHECK(input_error([&] { read_off(dir.path().string()); }) ==
        dir.path().string() + ": cannot open: Is a directory");
}

TEST_CASE("OFF writer refuses what it could not read back, and leaves no file", "[off]") {
  TempDir dir;
  const auto m = two_tetrahedra();
  const auto path = dir.file("out.off");
  SECTION("face index past the vertices") {
    auto F = m.F;
    F(2, 1) = 8;
    CHECK_THROWS_AS(write_off(path, m.V, F), std::invalid_argument);
  }
  SECTION("NaN coordinate") {
    auto V = m.V;
    V(3, 2) = std::nan("");
    CHECK_THROWS_AS(write_off(path, V, m.F), cmp::ComputationError);
  }
  SECTION("comment that would read as a packing line") {
    CHECK_THROWS_AS(write_off(path, m.V, m.F, {"box of chocolates"}), std::invalid_argument);
  }
  SECTION("shell counts not adding up to the vertices") {
    PackingInfo p;
    p.shell_vertex_counts = {4, 3};
    CHECK_THROWS_AS(write_off(path, m.V, m.F, {}, &p), std::invalid_argument);
  }
  SECTION("face across two shells") {
    PackingInfo p;
    p.shell_vertex_counts = {3, 5};
    CHECK_THROWS_AS(write_off(path, m.V, m.F, {}, &p), std::invalid_argument);
  }
  SECTION("box side not positive") {
    PackingInfo p;
    p.box = Eigen::Vector3d(1, -1, 1);
    CHECK_THROWS_AS(write_off(path, m.V, m.F, {}, &p), std::invalid_argument);
  }
  CHECK(dir.entries().empty());
}

TEST_CASE("OFF writer into a missing folder is an InputError", "[off]") {
  TempDir dir;
  const auto path = dir.file("no/such/folder/m.off");
  const auto m = two_tetrahedra();
  CHECK(input_error([&] { write_off(path, m.V, m.F); }) ==
        path + ": cannot write: No such file or directory");
}
