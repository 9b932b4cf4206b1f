#include "voxel/percolate_run.hpp"
#include "voxel/percolation_table.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace cmp::voxel;

namespace {
std::string write_input(const std::string& name, const std::string& text) {
  const auto path = (std::filesystem::temp_directory_path() / ("cmp_voxel_run_" + name)).string();
  std::ofstream(path) << text;
  return path;
}
// One sphere of radius 0.5 in a periodic box of side 2 (D0 = 1 from the radius), as an XYZ frame.
const std::string one_sphere =
    "1\nLattice=\"2 0 0 0 2 0 0 0 2\" Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"T T T\"\nX 1 1 1 0.5\n";

PercolatePlan plan_of(std::vector<double> deltas, std::vector<std::string> delta_names, std::vector<double> scales,
                      std::vector<std::string> scale_names) {
  PercolatePlan plan;
  plan.deltas = std::move(deltas);
  plan.delta_names = std::move(delta_names);
  plan.scales = std::move(scales);
  plan.scale_names = std::move(scale_names);
  plan.provenance = "test";
  return plan;
}
}  // namespace

TEST_CASE("percolate_runs go packings then scales then deltas", "[voxel][percolate_run]") {
  const auto runs = percolate_runs(2, 2, 3);
  REQUIRE(runs.size() == 12);
  CHECK((runs[0].packing == 0 && runs[0].scale == 0 && runs[0].delta == 0));
  CHECK((runs[1].packing == 0 && runs[1].scale == 0 && runs[1].delta == 1));
  CHECK((runs[3].packing == 0 && runs[3].scale == 1 && runs[3].delta == 0));
  CHECK((runs[6].packing == 1 && runs[6].scale == 0 && runs[6].delta == 0));
  CHECK((runs[11].packing == 1 && runs[11].scale == 1 && runs[11].delta == 2));
  CHECK(percolate_runs(3, 0, 2).empty());
}

TEST_CASE("read_packing_frames gives every frame of every input in order", "[voxel][percolate_run]") {
  const auto two = write_input("two.xyz", one_sphere + one_sphere), one = write_input("one.xyz", one_sphere);
  const auto frames = read_packing_frames({one, two}, {1.0, 0});
  REQUIRE(frames.packings.size() == 3);
  CHECK(frames.input_of == std::vector<std::size_t>{0, 1, 1});
  CHECK(frames.frame_of == std::vector<int>{0, 0, 1});
  CHECK(frames.several_frames);
  CHECK_FALSE(read_packing_frames({one, one}, {1.0, 0}).several_frames);
  CHECK_THROWS_AS(read_packing_frames({one, write_input("bad.xyz", "1\nno lattice\nX 1 1 1 0.5\n")}, {1.0, 0}),
                  cmp::InputError);
}

TEST_CASE("check_percolate_plan refuses a delta larger than the box and a scale of shells", "[voxel][percolate_run]") {
  const auto frames = read_packing_frames({write_input("a.xyz", one_sphere)}, {1.0, 0});
  CHECK_NOTHROW(check_percolate_plan(frames.packings, plan_of({0.5, 2}, {"0.5", "2"}, {1, 1.2}, {"1", "1.2"})));
  CHECK_THROWS_AS(check_percolate_plan(frames.packings, plan_of({0.5, 2.5}, {"0.5", "2.50"}, {1}, {"1"})),
                  cmp::UsageError);
  CHECK_THROWS_WITH(check_percolate_plan(frames.packings, plan_of({2.5}, {"2.50"}, {1}, {"1"})),
                    Catch::Contains("--delta 2.50 is larger than the box"));
  auto shells = frames.packings;
  shells[0].kind = cmp::packing::Packing::Kind::Shells;
  CHECK_THROWS_WITH(check_percolate_plan(shells, plan_of({0.5}, {"0.5"}, {1, 1.1}, {"1", "1.1"})),
                    Catch::Contains("--scale 1.1 applies to sphere packings"));
}

TEST_CASE("run_percolate gives a row per run and an image only when asked", "[voxel][percolate_run]") {
  const auto frames = read_packing_frames({write_input("b.xyz", one_sphere)}, {1.0, 0});
  auto plan = plan_of({0.5, 0.25}, {"0.50", "0.25"}, {1, 1.5}, {"1.0", "1.5"});
  const auto runs = percolate_runs(frames.packings.size(), plan.scales.size(), plan.deltas.size());
  std::vector<PercolateRunResult> results;
  std::vector<std::size_t> order;
  const auto warning = run_percolate(frames, plan, runs, [&](std::size_t r, PercolateRunResult& result) {
    order.push_back(r);
    results.push_back(std::move(result));
  });
  CHECK(warning.empty());  // one sphere: no pairs, the porosity is exact
  REQUIRE(results.size() == 4);
  CHECK(order == std::vector<std::size_t>{0, 1, 2, 3});
  const auto& cols = results[0].columns;
  REQUIRE(cols.size() == results[0].row.size());
  CHECK(std::vector<std::string>(cols.begin(), cols.begin() + 8) ==
        std::vector<std::string>{"file", "frame", "kind", "particles", "d0", "d0_source", "scale", "delta"});
  CHECK(results[0].row[7] == "0.50");          // delta as typed
  CHECK(results[2].row[6] == "1.5");           // the scale applied to the radii
  CHECK(results[1].summary.find("scale=1.0 delta=0.25 (8x8x8") != std::string::npos);
  CHECK(results[0].image.data.empty());
  CHECK(results[0].title.empty());
  plan.images = true;
  results.clear();
  run_percolate(frames, plan, {runs[1]}, [&](std::size_t, PercolateRunResult& result) { results.push_back(std::move(result)); });
  REQUIRE(results.size() == 1);
  CHECK(results[0].image.data.size() == 512u);
  CHECK(results[0].image.name == "cluster");
  CHECK(results[0].title.find("scale=1.0 delta=0.25") != std::string::npos);
  CHECK(results[0].title.substr(results[0].title.size() - 7) == " | test");
}

TEST_CASE("read_percolation_tables reads samples and refuses a table given twice", "[voxel][percolation_table]") {
  const auto a = write_input("a.csv",
                            "# connectivity=6\nfile,frame,kind,particles,delta,scale,porosity,percolates\n"
                            "p.xyz,0,spheres,64,0.1,1,0.7,1\np.xyz,0,spheres,64,0.1,1.2,0.5,0\n");
  const auto t = read_percolation_tables({a}, "porosity");
  REQUIRE(t.samples.size() == 2);
  CHECK(t.samples[0].particles == 64);
  CHECK(t.samples[0].percolates);
  CHECK_FALSE(t.samples[1].percolates);
  CHECK(t.samples[1].porosity == 0.5);
  CHECK(t.scales == std::set<std::string>{"1", "1.2"});
  CHECK(t.same == std::map<std::string, std::string>{{"connectivity", "6"}, {"kind", "spheres"}});
  CHECK_THROWS_WITH(read_percolation_tables({a, a}, "porosity"), Catch::Contains("is also at"));
  CHECK_THROWS_WITH(read_percolation_tables({a}, "porosity_voxels"), Catch::Contains("no column 'porosity_voxels'"));
  const auto b = write_input("b.csv", "# connectivity=26\nparticles,delta,porosity,percolates\n64,0.1,0.6,1\n");
  CHECK_THROWS_WITH(read_percolation_tables({a, b}, "porosity"), Catch::Contains("connectivity '26' differs from '6'"));
}
