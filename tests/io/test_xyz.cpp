// lib/io/xyz.hpp, xyz_frame.hpp, key_value_line.hpp: extended XYZ frames and trajectories.
#include "io/key_value_line.hpp"
#include "io/xyz.hpp"

#include "io_test_support.hpp"

#include <sstream>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// A frame with every column type, an awkward lattice and info values that need quoting.
XyzFrame sample_frame(int n, int seed) {
  const auto a = awkward_doubles();
  XyzFrame f;
  f.has_lattice = true;
  for (int k = 0; k < 9; ++k) f.lattice(k / 3, k % 3) = a[(k + seed) % a.size()] + (k % 4 == 0);
  f.pbc = {true, seed % 2 == 1, false};
  std::vector<std::string> species;
  mesh::VertexMatrix V(n, 3);
  Eigen::VectorXd radius(n);
  Eigen::MatrixXd velocity(n, 2);
  std::vector<int> shell;
  for (int i = 0; i < n; ++i) {
    species.push_back(i % 2 ? "He" : "X");
    for (int k = 0; k < 3; ++k) V(i, k) = a[(3 * i + k + seed) % a.size()];
    radius[i] = 0.5 + 1e-8 * i;
    velocity(i, 0) = -a[(i + seed) % a.size()];
    velocity(i, 1) = i / 3.0;
    shell.push_back(7 * i - 3);
  }
  f.set_species(species);
  f.set_positions(V);
  f.set_real_column("radius", radius);
  f.set_integer_column("shell", shell);
  f.set_real_column("velo", velocity);
  f.add_column(XyzColumn{"fixed", 'L', 1, std::vector<double>(n, 0.0), {}});
  if (n > 0) f.find("fixed")->values[0] = 1;
  f.add_column(XyzColumn{"tags", 'S', 2, {}, std::vector<std::string>(2 * n, "t")});
  f.set_info("tool", "shellpack");
  f.set_info("command", "shellpack jam -N 32 --seed \"7\" C:\\dir");
  f.set_info("step", std::to_string(seed));
  f.set_info("empty", "");
  return f;
}

void require_same(const XyzFrame& a, const XyzFrame& b) {
  REQUIRE(a.size() == b.size());
  CHECK(a.has_lattice == b.has_lattice);
  for (int k = 0; k < 9; ++k) CHECK(same_bits(a.lattice(k / 3, k % 3), b.lattice(k / 3, k % 3)));
  CHECK(a.pbc == b.pbc);
  CHECK(a.info == b.info);
  REQUIRE(a.columns.size() == b.columns.size());
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    const auto &x = a.columns[c], &y = b.columns[c];
    INFO("column " << x.name);
    CHECK(x.name == y.name);
    CHECK(x.type == y.type);
    CHECK(x.width == y.width);
    CHECK(x.strings == y.strings);
    REQUIRE(x.values.size() == y.values.size());
    for (std::size_t i = 0; i < x.values.size(); ++i) CHECK(same_bits(x.values[i], y.values[i]));
  }
}

}  // namespace

TEST_CASE("key=value comment lines parse like ASE's", "[xyz]") {
  const auto kv = parse_key_values(
      R"(Lattice="1 0 0 0 1 0 0 0 1" Properties=species:S:1:pos:R:3 flag  a=b=c q='x y' )"
      R"(e="say \"hi\"" br={1 2} sq=[3, 4] esc=a\ b)",
      "f", 2);
  const KeyValues expected = {{"Lattice", "1 0 0 0 1 0 0 0 1"},
                              {"Properties", "species:S:1:pos:R:3"},
                              {"flag", "T"},
                              {"a", "b=c"},
                              {"q", "x y"},
                              {"e", "say \"hi\""},
                              {"br", "1 2"},
                              {"sq", "3, 4"},
                              {"esc", "a b"}};
  CHECK(kv == expected);
  CHECK(parse_key_values("   ", "f", 2).empty());
  CHECK(input_error([] { parse_key_values("a=\"open", "f", 2); }) ==
        "f:2: unterminated quote: no closing '\"'");
  CHECK(input_error([] { parse_key_values("=5", "f", 2); }) == "f:2: '=5' without a key");
}

TEST_CASE("format_key_value quotes and escapes what ASE would split", "[xyz]") {
  CHECK(format_key_value("tool", "shellpack") == "tool=shellpack");
  CHECK(format_key_value("cmd", "a b") == "cmd=\"a b\"");
  CHECK(format_key_value("e", "") == "e=\"\"");
  CHECK(format_key_value("q", "x\"y\\z") == R"(q="x\"y\\z")");
  CHECK(format_key_value("n", "two\nlines") == "n=\"two lines\"");
  CHECK_THROWS_AS(format_key_value("bad key", "1"), std::invalid_argument);
  CHECK_THROWS_AS(format_key_value("", "1"), std::invalid_argument);
  for (const auto* v : {"a b", "x\"y\\z", "", "k=v", "{br}"}) {
    const auto kv = parse_key_values(format_key_value("k", v), "f", 1);
    REQUIRE(kv.size() == 1);
    CHECK(kv[0].second == v);
  }
}

TEST_CASE("extended XYZ round trip of a trajectory keeps every value bit for bit", "[xyz]") {
  TempDir dir;
  const std::vector<XyzFrame> frames = {sample_frame(5, 0), sample_frame(7, 1), sample_frame(0, 2)};
  write_xyz(dir.file("t.xyz"), frames);
  const auto back = read_xyz(dir.file("t.xyz"));
  REQUIRE(back.size() == frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    INFO("frame " << i);
    require_same(back[i], frames[i]);
    CHECK(back[i].file == dir.file("t.xyz"));
  }
  CHECK(back[0].line == 1);
  CHECK(back[1].line == 8);
  CHECK(back[2].line == 17);
  const auto V = back[1].positions();
  CHECK(V.rows() == 7);
  CHECK(same_bits(V(2, 1), frames[1].positions()(2, 1)));
  CHECK(back[1].species()[1] == "He");
  const auto velo = back[1].real_column("velo");
  CHECK(velo.cols() == 2);
  CHECK(velo(3, 1) == 1.0);
  CHECK(back[0].real_column("shell")(4, 0) == 25.0);
  CHECK(*back[0].find_info("command") == "shellpack jam -N 32 --seed \"7\" C:\\dir");
  CHECK(dir.entries() == std::vector<std::string>{"t.xyz"});
}

TEST_CASE("extended XYZ comment line starts with Lattice, Properties and pbc", "[xyz]") {
  std::ostringstream s;
  XyzWriter w(s);
  XyzFrame f;
  f.set_species({"X"});
  mesh::VertexMatrix V(1, 3);
  V << 0.1, -0.0, 1e-300;
  f.set_positions(V);
  f.has_lattice = true;
  f.lattice = Eigen::Matrix3d::Identity() * 2;
  f.lattice(1, 0) = 0.5;
  f.pbc = {true, true, true};
  f.set_info("tool", "jam2d");
  w.write(f);
  w.write(f);
  const std::string frame =
      "1\nLattice=\"2 0 0 0.5 2 0 0 0 2\" Properties=species:S:1:pos:R:3 pbc=\"T T T\" tool=jam2d\n"
      "X 0.1 -0 1e-300\n";
  CHECK(s.str() == frame + frame);
}

TEST_CASE("extended XYZ reader follows ASE's defaults", "[xyz]") {
  TempDir dir;
  const auto path = dir.file("a.xyz");
  SECTION("plain XYZ: default Properties, the title as bare keys") {
    write_text(path, "2\nplain title\nH 0 0 0\nO 1 2 3\n\n");
    const auto frames = read_xyz(path);
    REQUIRE(frames.size() == 1);
    CHECK(frames[0].species() == std::vector<std::string>{"H", "O"});
    CHECK(frames[0].positions()(1, 2) == 3.0);
    CHECK(frames[0].info == KeyValues{{"plain", "T"}, {"title", "T"}});
    CHECK_FALSE(frames[0].has_lattice);
    CHECK(frames[0].pbc == std::array<bool, 3>{false, false, false});
  }
  SECTION("a title with a stray quote is kept whole") {
    write_text(path, "1\nit's a molecule\nH 0 0 0\n");
    CHECK(read_xyz(path)[0].info == KeyValues{{"comment", "it's a molecule"}});
  }
  SECTION("a Lattice without pbc is periodic in all three directions") {
    write_text(path, "1\nlattice=\"1 0 0 0 1 0 0 0 1\"\nH 0 0 0\n");
    const auto f = read_xyz(path)[0];
    CHECK(f.has_lattice);
    CHECK(f.pbc == std::array<bool, 3>{true, true, true});
  }
  SECTION("OVITO-style file from tests/data/io") {
    const auto frames = read_xyz(CMP_SOURCE_DIR "/tests/data/io/ovito_style.xyz");
    REQUIRE(frames.size() == 2);
    CHECK(frames[1].size() == 3);
    CHECK(frames[1].lattice(2, 2) == 12.5);
    CHECK(frames[1].pbc == std::array<bool, 3>{true, true, false});
    CHECK(frames[1].real_column("Radius")(2, 0) == 0.75);
    CHECK(frames[1].real_column("Selection")(1, 0) == 1.0);
    CHECK(*frames[0].find_info("Time") == "0.5");
  }
}

TEST_CASE("extended XYZ reads standard input and writes standard output for '-'", "[xyz]") {
  {
    StdinFrom in("1\nProperties=pos:R:3\n1 2 3\n");
    CHECK(read_xyz("-")[0].positions()(0, 2) == 3.0);
  }
  StdoutTo out;
  XyzFrame f;
  f.set_integer_column("id", {4});
  write_xyz("-", {f});
  CHECK(out.text() == "1\nProperties=id:I:1 pbc=\"F F F\"\n4\n");
}

TEST_CASE("extended XYZ errors name the file and the line", "[xyz]") {
  const std::string ok =
      "2\nProperties=species:S:1:pos:R:3:id:I:1:on:L:1\nH 0 0 0 1 T\nH 1 1 1 2 F\n";
  const std::vector<BadInputCase> cases = {
      {"empty file", "", 0, "empty file"},
      {"count not a number", "two\n", 1, "expected the number of atoms, got 'two'"},
      {"count with more fields", "2 atoms\n", 1, "expected the number of atoms (one integer)"},
      {"negative count", "-1\n", 1, "expected the number of atoms in [0, 2147483647]"},
      {"no comment line", "2\n", 1, "unexpected end of file: expected the comment line"},
      {"truncated frame", "3\n\nH 0 0 0\nH 1 1 1\n", 4,
       "unexpected end of file: expected 3 atoms in the frame at line 1, got 2"},
      {"truncated second frame", ok + "2\n\nH 0 0 0\n", 7,
       "expected 2 atoms in the frame at line 5, got 1"},
      {"row too short", "2\n\nH 0 0 0\nH 1 1\n", 4,
       "expected 4 fields (species:S:1:pos:R:3), got 3"},
      {"row too long", "1\n\nH 0 0 0 9\n", 3, "expected 4 fields"},
      {"non-number in R", "1\n\nH 0 x 0\n", 3, "expected a number in column 'pos', got 'x'"},
      {"NaN in R", "1\n\nH 0 nan 0\n", 3, "(finite)"},
      {"non-integer in I", ok.substr(0, ok.size() - 12) + "H 1 1 1 2.5 F\n", 4,
       "expected an integer in column 'id'"},
      {"bad logical", ok.substr(0, ok.size() - 12) + "H 1 1 1 2 Y\n", 4,
       "expected T or F in column 'on', got 'Y'"},
      {"Lattice of 8 numbers", "1\nLattice=\"1 0 0 0 1 0 0 0\"\nH 0 0 0\n", 2,
       "Lattice must hold 9 numbers (a, b, c), got 8"},
      {"Lattice with a word", "1\nLattice=\"1 0 0 0 1 0 0 0 z\"\nH 0 0 0\n", 2,
       "expected a number in Lattice, got 'z'"},
      {"pbc of two flags", "1\npbc=\"T T\"\nH 0 0 0\n", 2, "pbc must be 3 flags T or F, got 'T T'"},
      {"pbc not T/F", "1\npbc=\"T X T\"\nH 0 0 0\n", 2, "pbc must be 3 flags"},
      {"Properties not triples", "1\nProperties=species:S:1:pos:R\nH 0 0 0\n", 2,
       "Properties must be name:type:width triples"},
      {"Properties bad type", "1\nProperties=pos:Q:3\n0 0 0\n", 2,
       "has type 'Q', expected R, I, S or L"},
      {"Properties zero width", "1\nProperties=pos:R:0\n0 0 0\n", 2,
       "expected a column width in Properties"},
      {"Properties twice the same column", "1\nProperties=a:R:1:a:R:1\n0 0\n", 2,
       "column 'a' appears twice"},
      {"30 bytes asking for terabytes (issue 15)", "1048576\nProperties=a:R:1048576\n", 2,
       "Properties ask for 1048576 fields per atom, more than a line of at most 1048576 bytes"},
      {"wide columns adding up past int", "1\nProperties=a:R:1048576:b:R:1048576:c:R:1048576\n", 2,
       "Properties ask for 3145728 fields per atom"},
      {"more atoms than the file holds", "2000000000\nProperties=pos:R:3\n0 0 0\n", 1,
       "the frame claims 2000000000 atoms of 3 fields, at least 12000000000 bytes"},
      {"a key without a name", "1\nProperties=pos:R:3 =\x1b" "esc\n0 0 0\n", 2, "'=\\x1Besc' without a key"},
      {"unterminated quote in an extended line", "1\nLattice=\"1 0 0 Properties=pos:R:3\n0 0 0\n",
       2, "unterminated quote"},
  };
  check_bad_inputs(cases, "bad.xyz", [](const std::string& path) { read_xyz(path); });
}

TEST_CASE("extended XYZ frame accessors check names, types and sizes", "[xyz]") {
  TempDir dir;
  const auto path = dir.file("a.xyz");
  write_text(path, "\n\n1\nProperties=species:S:1:x:R:1\nH 0.5\n");
  const auto f = read_xyz(path)[0];
  CHECK(input_error([&] { f.positions(); }) == path + ":3: no column pos:R:3 in Properties");
  CHECK(input_error([&] { f.real_column("species"); }) ==
        path + ":3: column 'species' holds strings, expected numbers");
  CHECK(input_error([&] { f.column("x", 'I'); }) == path + ":3: column x:R:1 found, expected x:I");
  CHECK(f.real_column("x")(0, 0) == 0.5);

  XyzFrame g;  // built in memory: programming errors, not input errors
  CHECK_THROWS_AS(g.positions(), std::invalid_argument);
  g.set_species({"A", "B"});
  CHECK_THROWS_AS(g.set_real_column("r", Eigen::VectorXd::Zero(3)), std::invalid_argument);
  CHECK_THROWS_AS(g.add_column(XyzColumn{"a:b", 'R', 1, {1, 2}, {}}), std::invalid_argument);
  CHECK_THROWS_AS(g.add_column(XyzColumn{"t", 'Z', 1, {1, 2}, {}}), std::invalid_argument);
  g.set_species({"C", "D"});  // replaced in place
  CHECK(g.columns.size() == 1);
  CHECK(g.species() == std::vector<std::string>{"C", "D"});
  g.set_info("k", "1");
  g.set_info("k", "2");
  CHECK(g.info == KeyValues{{"k", "2"}});
}

TEST_CASE("extended XYZ writer refuses frames it could not read back", "[xyz]") {
  TempDir dir;
  const auto path = dir.file("out.xyz");
  auto f = sample_frame(3, 0);
  SECTION("species with a space") {
    f.find("species")->strings[1] = "H e";
    CHECK_THROWS_AS(write_xyz(path, {f}), std::invalid_argument);
  }
  SECTION("NaN position") {
    f.find("pos")->values[4] = std::nan("");
    CHECK_THROWS_AS(write_xyz(path, {f}), cmp::ComputationError);
  }
  SECTION("fractional integer") {
    f.find("shell")->values[0] = 0.5;
    CHECK_THROWS_AS(write_xyz(path, {f}), std::invalid_argument);
  }
  SECTION("columns of unequal sizes") {
    f.find("radius")->values.pop_back();
    CHECK_THROWS_AS(write_xyz(path, {f}), std::invalid_argument);
  }
  SECTION("reserved info key") {
    f.info.emplace_back("pbc", "T T T");
    CHECK_THROWS_AS(write_xyz(path, {f}), std::invalid_argument);
  }
  SECTION("a good frame, then a bad one: no half trajectory") {
    auto bad = f;
    bad.find("pos")->values[0] = INFINITY;
    CHECK_THROWS_AS(write_xyz(path, {f, bad}), cmp::ComputationError);
  }
  CHECK(dir.entries().empty());
  CHECK(input_error([&] { write_xyz(dir.file("none/out.xyz"), {f}); }) ==
        dir.file("none/out.xyz") + ": cannot write: No such file or directory");
}
