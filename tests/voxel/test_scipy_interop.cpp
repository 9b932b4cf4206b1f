// Hidden test case driven by tests/interop/percolate_scipy.sh: labels the images that
// percolate_scipy.py wrote into $CMP_INTEROP_DIR (one "<name>.u8" per line of images.txt:
// "name nx ny nz connectivity periodic_xyz"), writing "<name>.i32" (native int32), which
// the Python side compares with scipy.ndimage.label.
#include "voxel/label_components.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace cmp::voxel;

TEST_CASE("label the images written for scipy", "[.scipy]") {
  const char* dir = std::getenv("CMP_INTEROP_DIR");
  if (!dir || !*dir) FAIL("set CMP_INTEROP_DIR to the folder of the images");
  std::ifstream list(std::string(dir) + "/images.txt");
  REQUIRE(list);
  std::string line;
  int images = 0;
  while (std::getline(list, line)) {
    std::istringstream in(line);
    std::string name, periodic;
    std::array<int, 3> d{};
    int conn = 6;
    REQUIRE(in >> name >> d[0] >> d[1] >> d[2] >> conn >> periodic);
    std::vector<std::uint8_t> img(static_cast<std::size_t>(d[0]) * d[1] * d[2]);
    std::ifstream(std::string(dir) + "/" + name + ".u8", std::ios::binary)
        .read(reinterpret_cast<char*>(img.data()), static_cast<std::streamsize>(img.size()));
    LabelOptions o;
    o.connectivity = static_cast<Connectivity>(conn);
    for (int a = 0; a < 3; ++a) o.periodic[a] = periodic[a] == '1';
    std::vector<std::int32_t> labels;
    label_components(img.data(), d, labels, o);
    std::ofstream(std::string(dir) + "/" + name + ".i32", std::ios::binary)
        .write(reinterpret_cast<const char*>(labels.data()), static_cast<std::streamsize>(labels.size() * 4));
    ++images;
  }
  CHECK(images > 0);
}
