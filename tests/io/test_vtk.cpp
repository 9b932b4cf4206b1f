// lib/io/vtk.hpp: voxel images as binary big-endian STRUCTURED_POINTS, strict header reading.
#include "io/vtk.hpp"

#include "core/errors.hpp"

#include "io_test_support.hpp"

#include <bit>
#include <cmath>

#include <climits>
#include <cstdlib>
#include <sstream>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

template <class T>
VoxelImage<T> pattern_image(std::array<int, 3> dims) {
  VoxelImage<T> img(dims);
  img.origin = Eigen::Vector3d(0.1, -0.0, 1e-300);
  img.spacing = Eigen::Vector3d(1.0 / 3.0, 1e-8, 2.5);
  img.name = "solid";
  const auto a = awkward_doubles();
  for (std::size_t i = 0; i < img.data.size(); ++i) {
    if constexpr (std::same_as<T, std::uint8_t>)
      img.data[i] = static_cast<T>(i * 37 % 256);
    else if constexpr (std::same_as<T, std::int32_t>)
      img.data[i] = i == 0 ? INT_MIN : i == 1 ? INT_MAX : static_cast<T>(i * 1000003) - 7;
    else
      img.data[i] = static_cast<T>(a[i % a.size()]) * static_cast<T>(i % 3 ? 1 : -1);
  }
  return img;
}

template <class T>
void require_same(const VoxelImage<T>& a, const VoxelImage<T>& b) {
  CHECK(a.dims == b.dims);
  for (int k = 0; k < 3; ++k) {
    CHECK(same_bits(a.origin[k], b.origin[k]));
    CHECK(same_bits(a.spacing[k], b.spacing[k]));
  }
  CHECK(a.name == b.name);
  REQUIRE(a.data.size() == b.data.size());
  CHECK(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(T)) == 0);
}

const std::string kHeader =
    "# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 1\n"
    "ORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 4\n";

}  // namespace

TEMPLATE_TEST_CASE("VTK round trip keeps every voxel, origin and spacing", "[vtk]", std::uint8_t,
                   std::int32_t, float, double) {
  TempDir dir;
  const auto img = pattern_image<TestType>({7, 5, 3});
  write_vtk(dir.file("i.vtk"), img, "percolate 0.1 pack.off --delta 0.04");
  require_same(read_vtk<TestType>(dir.file("i.vtk")), img);
  const auto info = read_vtk_info(dir.file("i.vtk"));
  CHECK(info.type == vtk_type_name<TestType>());
  CHECK(info.title == "percolate 0.1 pack.off --delta 0.04");
  CHECK(info.binary);
  CHECK(info.dims == std::array<int, 3>{7, 5, 3});
  CHECK(info.data_line == 11);
  CHECK(dir.entries() == std::vector<std::string>{"i.vtk"});
}

TEST_CASE("VTK images larger than one conversion chunk round trip", "[vtk]") {
  TempDir dir;
  const auto img = pattern_image<double>({101, 67, 11});  // 74k values: two chunks
  write_vtk(dir.file("big.vtk"), img, "big");
  require_same(read_vtk<double>(dir.file("big.vtk")), img);
}

TEST_CASE("VTK file layout: header, big-endian values x fastest, final newline", "[vtk]") {
  VoxelImage<std::int32_t> img({2, 1, 2});
  img.spacing = Eigen::Vector3d::Constant(0.04);
  img(0, 0, 0) = 0x01020304;
  img(1, 0, 0) = -2;
  img(0, 0, 1) = 5;
  img(1, 0, 1) = 256;
  CHECK(img.index(1, 0, 1) == 3);
  std::ostringstream s;
  write_vtk(s, img, "line one\nline two");
  const std::string header =
      "# vtk DataFile Version 3.0\nline one line two\nBINARY\nDATASET STRUCTURED_POINTS\n"
      "DIMENSIONS 2 1 2\nORIGIN 0 0 0\nSPACING 0.04 0.04 0.04\nPOINT_DATA 4\n"
      "SCALARS values int 1\nLOOKUP_TABLE default\n";
  const std::string data("\x01\x02\x03\x04\xff\xff\xff\xfe\x00\x00\x00\x05\x00\x00\x01\x00\n", 17);
  CHECK(s.str() == header + data);
}

TEST_CASE("VTK title is cut to 255 characters", "[vtk]") {
  std::ostringstream s;
  write_vtk(s, VoxelImage<float>({1, 1, 1}), std::string(300, 'x'));
  CHECK_THAT(s.str(), Contains("\n" + std::string(255, 'x') + "\nBINARY\n"));
}

TEST_CASE("VTK reader reads ASCII files too", "[vtk]") {
  const auto img = read_vtk<std::uint8_t>(CMP_SOURCE_DIR "/tests/data/io/ascii_uint8_3x2x2.vtk");
  CHECK(img.dims == std::array<int, 3>{3, 2, 2});
  CHECK(img.name == "pore");
  CHECK(img.spacing[0] == 0.5);
  CHECK(img(2, 1, 1) == 255);
  CHECK(img(1, 0, 0) == 1);
  CHECK(img(0, 1, 0) == 3);
  CHECK(img(0, 0, 1) == 6);
  TempDir dir;
  write_text(dir.file("f.vtk"),
             kHeader + "SCALARS v float\nLOOKUP_TABLE default\n0.1 -0\n1e-8\n\n3\n");
  const auto f = read_vtk<float>(dir.file("f.vtk"));
  CHECK(same_bits(f.data[0], 0.1f));
  CHECK(same_bits(f.data[1], -0.0f));
  CHECK(same_bits(f.data[2], 1e-8f));
}

TEST_CASE("VTK reads standard input and writes standard output for '-'", "[vtk]") {
  const auto img = pattern_image<float>({3, 2, 2});
  std::string bytes;
  {
    StdoutTo out;
    write_vtk("-", img, "t");
    bytes = out.text();
  }
  StdinFrom in(bytes);
  require_same(read_vtk<float>("-"), img);
}

TEST_CASE("VTK errors name the file, the line and what was found", "[vtk]") {
  const std::string lut = "SCALARS v unsigned_char 1\nLOOKUP_TABLE default\n";
  const std::vector<BadInputCase> cases = {
      {"empty file", "", 0, "empty file"},
      {"not VTK", "OFF\n", 1, "not a VTK legacy file"},
      {"no mode line", "# vtk DataFile Version 3.0\ntitle\n", 2,
       "unexpected end of file: expected ASCII or BINARY"},
      {"bad mode", "# vtk DataFile Version 3.0\nt\nTEXT\n", 3,
       "expected ASCII or BINARY on the third line"},
      {"other dataset", "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n", 4,
       "dataset 'UNSTRUCTURED_GRID' is not supported"},
      {"zero dimension",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 0 1 1\n", 5,
       "expected a dimension in [1, 2147483647], got '0'"},
      {"two dimensions",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2\n", 5,
       "expected 'DIMENSIONS nx ny nz'"},
      {"negative spacing", kHeader.substr(0, kHeader.find("SPACING")) + "SPACING 1 -1 1\n", 7,
       "a spacing '-1' is not positive"},
      {"POINT_DATA disagrees", kHeader.substr(0, kHeader.find("POINT_DATA")) + "POINT_DATA 5\n", 8,
       "POINT_DATA 5 disagrees with DIMENSIONS 2 2 1 (4 points)"},
      {"CELL_DATA", kHeader.substr(0, kHeader.find("POINT_DATA")) + "CELL_DATA 1\n", 8,
       "CELL_DATA is not supported"},
      {"VECTORS", kHeader + "VECTORS v float\n", 9, "expected 'SCALARS name type'"},
      {"three components", kHeader + "SCALARS v float 3\n", 9, "SCALARS with '3' components"},
      {"no LOOKUP_TABLE", kHeader + "SCALARS v unsigned_char\n0 1 2 3\n", 10,
       "expected 'LOOKUP_TABLE default'"},
      {"wrong type", kHeader + "SCALARS v float\nLOOKUP_TABLE default\n0 0 0 0\n", 9,
       "scalar type is 'float', expected 'unsigned_char'"},
      {"ASCII value out of range", kHeader + lut + "0 1 256 3\n", 11, "in [0, 255], got '256'"},
      {"ASCII too few values", kHeader + lut + "0 1\n2\n", 12,
       "unexpected end of file: expected 4 values, got 3"},
      {"ASCII too many values", kHeader + lut + "0 1 2 3\n4\n", 12,
       "more than the 4 values of POINT_DATA"},
      {"ASCII junk", kHeader + lut + "0 x 2 3\n", 11,
       "expected a value of type unsigned_char, got 'x'"},
      {"binary truncated",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 1\n"
       "POINT_DATA 4\n" +
           lut + std::string("\x01\x02\x03", 3),
       9, "unexpected end of file: expected 4 values of unsigned_char (4 bytes), got 3 bytes"},
      {"dimensions whose product wraps 64 bits (issue 15)",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\n"
       "DIMENSIONS 2097152 2097152 4194304\nPOINT_DATA 0\n" + lut,
       5, "DIMENSIONS 2097152 2097152 4194304 make more than 2^40 points"},
      {"a terabyte claimed by a short file",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\n"
       "DIMENSIONS 1024 1024 1048576\nPOINT_DATA 1099511627776\n" + lut + "abcd",
       9, "unexpected end of file: expected 1099511627776 values of unsigned_char "
          "(1099511627776 bytes), got 4 bytes"},
      {"FIELD without its count", kHeader.substr(0, kHeader.find("POINT_DATA")) + "FIELD FieldData\n",
       8, "expected 'FIELD name n'"},
      {"FIELD array of an unknown type",
       kHeader.substr(0, kHeader.find("POINT_DATA")) + "FIELD FieldData 1\ndelta 1 1 quaternion\n",
       9, "FIELD array type 'quaternion' is not supported"},
      {"FIELD value not a number",
       kHeader.substr(0, kHeader.find("POINT_DATA")) + "FIELD FieldData 1\ndelta 1 1 double\nabc\n",
       10, "expected a FIELD value, got 'abc'"},
      {"binary followed by junk",
       "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\n"
       "DIMENSIONS 2 2 1\nPOINT_DATA 4\n" +
           lut + "abcd\nSCALARS w float\n",
       0, "unexpected content after the 4 values"},
  };
  check_bad_inputs(cases, "bad.vtk", [](const std::string& path) { read_vtk<std::uint8_t>(path); });
}

TEST_CASE("VTK from a pipe claiming a terabyte fails on the missing bytes and not on memory", "[vtk]") {
  // Read from standard input nothing tells the size: the image must grow as bytes arrive.
  StdinFrom in(
      "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 1024 1024 1048576\n"
      "POINT_DATA 1099511627776\nSCALARS v unsigned_char\nLOOKUP_TABLE default\n" +
      std::string(200, '\x01'));
  CHECK_THAT(input_error([] { read_vtk<std::uint8_t>("-"); }),
             StartsWith("<stdin>:9: unexpected end of file: expected 1099511627776 values") &&
                 Contains("got 200 bytes"));
}

TEST_CASE("VTK field data round trip in binary and ASCII and files without it", "[vtk]") {
  TempDir dir;
  auto img = pattern_image<float>({3, 2, 2});
  img.field_data = {{"delta", 0.04}, {"D0", 1.0 / 3.0}, {"count", 10.0}};
  write_vtk(dir.file("f.vtk"), img, "t");
  const auto back = read_vtk<float>(dir.file("f.vtk"));
  require_same(back, img);
  CHECK(back.field_data == img.field_data);
  CHECK(read_vtk_info(dir.file("f.vtk")).field_data == img.field_data);
  // A value whose big-endian bytes hold a line break (0x0a) and '#' must not confuse the reader.
  img.field_data = {{"tricky", std::bit_cast<double>(0x0A0A230A0A0A0A0AULL)}};
  write_vtk(dir.file("g.vtk"), img, "t");
  CHECK(read_vtk<float>(dir.file("g.vtk")).field_data == img.field_data);
  // ASCII field data as other writers make it, arrays of several values skipped
  write_text(dir.file("a.vtk"), kHeader.substr(0, kHeader.find("POINT_DATA")) +
                                    "FIELD FieldData 2\nTIME 1 1 double\n2.5\nlist 2 2 int\n1 2\n3 4\n" +
                                    "POINT_DATA 4\nSCALARS v unsigned_char 1\nLOOKUP_TABLE default\n0 1 2 3\n");
  const auto a = read_vtk<std::uint8_t>(dir.file("a.vtk"));
  CHECK(a.field_data == std::vector<std::pair<std::string, double>>{{"TIME", 2.5}});
  CHECK(a.data[3] == 3);
  // no field data: none read back
  write_vtk(dir.file("n.vtk"), pattern_image<float>({2, 2, 2}), "t");
  CHECK(read_vtk<float>(dir.file("n.vtk")).field_data.empty());
  // bad field data refused by the writer
  img.field_data = {{"two words", 1.0}};
  CHECK_THROWS_AS(write_vtk(dir.file("b.vtk"), img, "t"), std::invalid_argument);
  img.field_data = {{"x", NAN}};  // a computed quantity gone wrong: the run fails (exit 1)
  CHECK_THROWS_AS(write_vtk(dir.file("b.vtk"), img, "t"), ComputationError);
}

TEST_CASE("VTK field data and origin and spacing as VTK's own reader sees them", "[vtk]") {
  TempDir dir;
  auto img = pattern_image<std::uint8_t>({4, 3, 2});
  img.origin = Eigen::Vector3d(0.125, 0.25, 1.0 / 3.0);
  img.spacing = Eigen::Vector3d(0.25, 0.5, 0.75);
  img.field_data = {{"delta", 0.04}, {"D0", 1.0 / 3.0}};
  write_vtk(dir.file("f.vtk"), img, "percolate test");
  const std::string script =
      "import sys, vtk\n"
      "r = vtk.vtkStructuredPointsReader(); r.SetFileName(sys.argv[1]); r.ReadAllFieldsOn(); r.Update()\n"
      "o = r.GetOutput(); fd = o.GetFieldData()\n"
      "assert o.GetDimensions() == (4, 3, 2), o.GetDimensions()\n"
      "assert o.GetOrigin() == (0.125, 0.25, 1.0 / 3.0), o.GetOrigin()\n"
      "assert o.GetSpacing() == (0.25, 0.5, 0.75), o.GetSpacing()\n"
      "assert fd.GetNumberOfArrays() == 2, fd.GetNumberOfArrays()\n"
      "assert fd.GetArray('delta').GetValue(0) == 0.04\n"
      "assert fd.GetArray('D0').GetValue(0) == 1.0 / 3.0\n"
      "s = o.GetPointData().GetScalars()\n"
      "assert s.GetNumberOfTuples() == 24 and s.GetValue(23) == 23 * 37 % 256, s.GetValue(23)\n"
      "import meshio\n"  // meshio reads the image too (it drops dataset-level field data)
      "m = meshio.read(sys.argv[1])\n"
      "assert m.points.shape == (24, 3) and m.point_data['solid'][23] == 23 * 37 % 256\n";
  write_text(dir.file("check.py"), script);
  CHECK(std::system(("/usr/bin/python3 " + dir.file("check.py") + " " + dir.file("f.vtk")).c_str()) == 0);
}

TEST_CASE("VTK reader with the wrong type names the type found", "[vtk]") {
  TempDir dir;
  write_vtk(dir.file("i.vtk"), pattern_image<std::uint8_t>({2, 2, 2}), "t");
  CHECK(input_error([&] { read_vtk<float>(dir.file("i.vtk")); }) ==
        dir.file("i.vtk") + ":9: scalar type is 'unsigned_char', expected 'float'");
  CHECK(input_error([&] { read_vtk<float>(dir.file("none.vtk")); }) ==
        dir.file("none.vtk") + ": cannot open: No such file or directory");
}

TEST_CASE("VTK writer refuses inconsistent images and leaves no file", "[vtk]") {
  TempDir dir;
  const auto path = dir.file("o.vtk");
  auto img = pattern_image<float>({2, 3, 4});
  SECTION("data size") {
    img.data.pop_back();
    CHECK_THROWS_AS(write_vtk(path, img, "t"), std::invalid_argument);
  }
  SECTION("name with a space") {
    img.name = "two words";
    CHECK_THROWS_AS(write_vtk(path, img, "t"), std::invalid_argument);
  }
  SECTION("zero spacing") {
    img.spacing[1] = 0;
    CHECK_THROWS_AS(write_vtk(path, img, "t"), std::invalid_argument);
  }
  CHECK(dir.entries().empty());
  CHECK(input_error([&] {
          write_vtk(dir.file("no/o.vtk"), pattern_image<float>({1, 1, 1}), "t");
        }) == dir.file("no/o.vtk") + ": cannot write: No such file or directory");
}
