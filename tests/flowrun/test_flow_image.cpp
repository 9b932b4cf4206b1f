#include "flowrun/flow_image.hpp"

#include "core/errors.hpp"
#include "io/vtk.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace cmp;
using namespace cmp::flowrun;

namespace {
std::string scratch(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("flowrun_test_" + name)).string();
}
}  // namespace

TEST_CASE("parse_dims takes NXxNYxNZ and nothing else", "[flowrun][image]") {
  CHECK(parse_dims("96x96x96") == std::array<int, 3>{96, 96, 96});
  CHECK(parse_dims("3x4x5") == std::array<int, 3>{3, 4, 5});
  for (const char* bad : {"96x96", "0x1x1", "1x1x1x1", "axbxc", "2x2x-1", "1.5x2x2", "", "x1x1"})
    CHECK_THROWS_AS(parse_dims(bad), UsageError);
  CHECK_THROWS_WITH(parse_dims("99999x99999x99999"), Catch::Contains("2^31 - 1 voxels or more"));
  CHECK_THROWS_WITH(parse_dims("2048x1024x1024"), Catch::Contains("2^31 - 1 voxels or more"));
  CHECK(parse_dims("2047x1024x1024") == std::array<int, 3>{2047, 1024, 1024});
}

TEST_CASE("read_vtk_image takes every scalar type, non-zero as fluid, and percolate's field data",
          "[flowrun][image]") {
  io::VoxelImage<float> img({3, 2, 2}, 0.0f);
  img.data[1] = 0.5f;
  img.data[7] = -2.0f;
  img.origin = Eigen::Vector3d(0.05, 0.05, 0.05);
  img.spacing = Eigen::Vector3d(0.1, 0.1, 0.1);
  img.field_data = {{"delta", 0.1}, {"d0", 1.0}, {"scale", 1.2}, {"porosity", 0.4}, {"other", -3}};
  const auto path = scratch("float.vtk");
  io::write_vtk(path, img, "test");
  const auto f = read_vtk_image(path);
  CHECK(f.dims == std::array<int, 3>{3, 2, 2});
  CHECK(f.fluid_voxels() == 2);
  CHECK(f.fluid[1] == 1);
  CHECK(f.fluid[7] == 1);
  CHECK(f.fluid[0] == 0);
  CHECK(f.delta == 0.1);
  CHECK(f.d0 == 1.0);
  CHECK(f.scale == 1.2);
  CHECK(f.porosity == 0.4);
  CHECK(f.spacing[0] == 0.1);
  CHECK(f.format == "vtk");

  io::VoxelImage<std::uint8_t> plain({2, 2, 2}, 1);  // no field data: lattice units
  io::write_vtk(path, plain, "plain");
  const auto g = read_vtk_image(path);
  CHECK_FALSE(g.delta.has_value());
  CHECK_FALSE(g.d0.has_value());
  CHECK(g.fluid_voxels() == 8);

  img.field_data = {{"porosity", 1.5}};
  io::write_vtk(path, img, "bad porosity");
  CHECK_THROWS_WITH(read_vtk_image(path), Catch::Contains("porosity"));
  std::remove(path.c_str());
}

TEST_CASE("read_vtk_image refuses other datasets and scalar types with their line", "[flowrun][image]") {
  const auto path = scratch("bad.vtk");
  {
    std::ofstream out(path);
    out << "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 1 1 2\n"
           "POINT_DATA 2\nSCALARS v short 1\nLOOKUP_TABLE default\n1 0\n";
  }
  CHECK_THROWS_WITH(read_vtk_image(path), Catch::Contains("scalar type 'short' is not supported"));
  {
    std::ofstream out(path);
    out << "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  }
  CHECK_THROWS_AS(read_vtk_image(path), InputError);
  CHECK_THROWS_WITH(read_vtk_image(path), Catch::Contains("STRUCTURED_POINTS"));
  std::remove(path.c_str());
}

TEST_CASE("read_raw_image checks the size against --dims", "[flowrun][image]") {
  const auto path = scratch("image.raw");
  {
    std::ofstream out(path, std::ios::binary);
    const char bytes[8] = {0, 1, 2, 0, 0, 0, 9, 0};
    out.write(bytes, 8);
  }
  const auto f = read_raw_image(path, {2, 2, 2});
  CHECK(f.fluid == std::vector<std::uint8_t>{0, 1, 1, 0, 0, 0, 1, 0});
  CHECK(f.format == "raw");
  CHECK_THROWS_WITH(read_raw_image(path, {3, 3, 3}), Catch::Contains("holds 8 bytes, --dims 3x3x3 needs 27"));
  CHECK_THROWS_WITH(read_raw_image(path, {1, 1, 2}), Catch::Contains("holds 8 bytes, --dims 1x1x2 needs 2"));
  std::remove(path.c_str());
}
