// rndmesh: triangulated sphere meshes and their quality (thesis Appendix A).
//   rndmesh icosa --level 4 -o cell.off       iterative subdivision (simple, tetra, octa, icosa)
//   rndmesh random -n 1000 --seed 7 -o cell.off   annealed random points + spherical Delaunay
//   rndmesh stats cell.off > cell.csv         quality metrics of any closed triangle mesh
#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/off.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"
#include "spheremesh/sphere_mesh_report.hpp"
#include "spheremesh/subdivision.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <atomic>
#include <iostream>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  cli::SeedOptions seeding;          // random: --seed, --seeds, --resume
  std::string output = "-";
  int level = 1;
  double radius = 1.0;
  spheremesh::AnnealingParameters annealing;
  std::string trace;                 // random: per-temperature CSV
  std::vector<std::string> inputs;   // stats
};

// Writes the mesh with its provenance and quality as "# key=value" comments; returns a
// one-line summary of how good it is, for stderr.
std::string write_mesh(const Options& o, const std::string& provenance, const mesh::TriMesh& m,
                       std::vector<std::string> comments) {
  const auto report = spheremesh::sphere_mesh_report(m.V, m.F);
  comments.insert(comments.begin(), provenance);
  for (const auto& [key, value] : spheremesh::report_fields(report)) comments.push_back(key + "=" + value);
  io::write_off(o.output, m.V, m.F, comments);
  return fmt::format("{}: {} vertices, {} triangles, q_A={:.3f} q_theta={:.3f} q={:.3f}, area error {:.2e}, "
                     "volume error {:.2e}",
                     o.output == "-" ? "stdout" : o.output, report.vertices, report.faces, report.q_area,
                     report.q_angle, report.q_radius_ratio, report.area_rel_error,
                     report.volume_divergence_rel_error);
}

void run_subdivision(const Options& o, spheremesh::Subdivision scheme, const std::string& provenance) {
  const auto m = spheremesh::subdivided_sphere(scheme, o.level, o.radius);
  const auto summary = write_mesh(o, provenance, m,
                                  {"method=" + spheremesh::subdivision_name(scheme), "level=" + std::to_string(o.level),
                                   "radius=" + io::format_number(o.radius)});
  if (!o.common.quiet) std::cerr << "rndmesh: " << summary << "\n";
}

void write_trace(const std::string& path, const std::string& provenance, const spheremesh::AnnealingParameters& p,
                 const spheremesh::AnnealingResult& r) {
  io::AtomicOutput out(path);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  for (const auto& [key, value] : spheremesh::annealing_fields(p, r)) csv.meta(key, value);
  csv.header({"anneal", "temperature_en", "acceptance", "energy_per_point_en"});
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const auto& s = r.steps[i];
    csv.row({std::to_string(i + 1), io::format_number(s.temperature), io::format_number(s.acceptance),
             io::format_number(s.energy_per_point)});
  }
  out.commit();
}

void run_random(const Options& o, const std::vector<std::uint64_t>& all_seeds, const std::string& provenance) {
  // One mesh per seed; seeds are independent Markov chains, run in parallel. With --resume a
  // seed whose files all exist is skipped: files appear only complete (io::AtomicOutput).
  std::vector<std::uint64_t> seeds;
  for (const auto s : all_seeds) {
    const std::string seed = std::to_string(s);
    std::vector<std::string> outputs{cli::expand_pattern(o.output, "seed", seed)};
    if (!o.trace.empty()) outputs.push_back(cli::expand_pattern(o.trace, "seed", seed));
    if (!(o.seeding.resume && cli::outputs_complete(outputs))) seeds.push_back(s);
  }
  if (seeds.size() < all_seeds.size() && !o.common.quiet)
    std::cerr << "rndmesh: --resume: " << all_seeds.size() - seeds.size() << " of " << all_seeds.size()
              << " seeds already done\n";
  const long n = static_cast<long>(seeds.size());
  cli::ProgressBar bar("annealing", static_cast<double>(n) * o.annealing.anneals, o.common.quiet);
  std::atomic<long> anneals_done{0};
  std::vector<std::string> summaries(n);
  parallel_for_each_job(n, [&](long k) {
    auto p = o.annealing;
    p.seed = seeds[k];
    const std::string seed = std::to_string(p.seed);
    const auto annealed = spheremesh::anneal_on_sphere(p, {}, [&](int, int) {
      const long done = ++anneals_done;
      bar.update(static_cast<double>(done));  // from any thread: the bar locks
    });
    const mesh::TriMesh m{annealed.points, spheremesh::spherical_delaunay(annealed.points)};
    Options single = o;
    single.output = cli::expand_pattern(o.output, "seed", seed);
    std::vector<std::string> comments{"method=random"};
    for (const auto& [key, value] : spheremesh::annealing_fields(p, annealed)) comments.push_back(key + "=" + value);
    summaries[k] = write_mesh(single, provenance, m, comments);
    // Wall time goes to stderr only: the files of a seed are the same bytes on every run.
    summaries[k] += fmt::format(", Monte Carlo {:.2f} s ({:.3g} trial moves/s)", annealed.seconds,
                                annealed.seconds > 0 ? annealed.attempted / annealed.seconds : 0.0);
    if (!o.trace.empty()) write_trace(cli::expand_pattern(o.trace, "seed", seed), provenance, p, annealed);
  });
  bar.finish();
  if (!o.common.quiet)
    for (const auto& line : summaries) std::cerr << "rndmesh: " << line << "\n";
}

void run_stats(const Options& o, const std::string& provenance) {
  // Read and measure every file (in parallel), then write in input order; the first bad file
  // in that order is the error reported, and nothing is written.
  const long n = static_cast<long>(o.inputs.size());
  std::vector<spheremesh::SphereMeshReport> reports(n);
  parallel_for_each_job(n, [&](long i) {
    const auto off = io::read_off(o.inputs[i]);
    if (off.F.rows() == 0) throw InputError(o.inputs[i], 0, "the mesh has no triangles");
    reports[i] = spheremesh::sphere_mesh_report(off.V, off.F);
  });
  io::AtomicOutput out(o.output);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  std::vector<std::string> header{"file"};
  for (const auto& field : spheremesh::report_fields(reports.front())) header.push_back(field.first);
  csv.header(header);
  for (long i = 0; i < n; ++i) {
    std::vector<std::string> row{o.inputs[i]};
    for (const auto& field : spheremesh::report_fields(reports[i])) row.push_back(field.second);
    csv.row(row);
    if (!reports[i].closed_manifold && !o.common.quiet)
      std::cerr << "rndmesh: warning: " << o.inputs[i] << " is not a closed manifold: volumes are not meaningful\n";
  }
  out.commit();
}

}  // namespace

// The most vertices a subdivided sphere may have (2^24: about 1.2 GB of mesh).
constexpr long kMaxMeshVertices = 1L << 24;

int main(int argc, char** argv) {
  return cli::run_tool("rndmesh", [&] {
    Options o;
    cli::Tool tool("rndmesh", "Triangulated sphere meshes and their quality metrics (thesis Appendix A).");
    auto* app = &tool.app();
    app->require_subcommand(1);
    tool.add_common(*app, o.common, cli::Tool::kQuiet);

    std::vector<std::pair<CLI::App*, spheremesh::Subdivision>> schemes;
    for (const auto& [name, scheme, what] :
         {std::tuple{"simple", spheremesh::Subdivision::Simple, "cube, bisection of the longest edge per level"},
          std::tuple{"tetra", spheremesh::Subdivision::Tetrahedron, "tetrahedron, quadrisection per level"},
          std::tuple{"octa", spheremesh::Subdivision::Octahedron, "octahedron, quadrisection per level"},
          std::tuple{"icosa", spheremesh::Subdivision::Icosahedron, "icosahedron, quadrisection per level"}}) {
      auto* sub = app->add_subcommand(name, std::string("iterative sphere mesh: ") + what);
      tool.add_int(*sub, "-l,--level", o.level, "subdivision level; 1 is the base polyhedron", cli::closed(1, spheremesh::kMaxSubdivisionLevel));
      tool.add_double(*sub, "-r,--radius", o.radius, "sphere radius [length units]", cli::positive());
      tool.add_output(*sub, "-o,--output", o.output, "output OFF file ('-': stdout)");
      tool.add_common(*sub, o.common, cli::Tool::kQuiet);
      schemes.emplace_back(sub, scheme);
    }

    auto& a = o.annealing;
    auto* random = app->add_subcommand("random", "N annealed random points on the sphere + spherical Delaunay (A.2.2)");
    tool.add_int(*random, "-n,--points", a.points, "number of vertices N", cli::at_least(4))->required();
    tool.add_double(*random, "-r,--radius", a.radius, "sphere radius R [length units]; r_v = 2R/sqrt(N)", cli::positive());
    tool.add_double(*random, "--tmax", a.t_max, "first annealing temperature [energy units]", cli::positive());
    tool.add_double(*random, "--tmin", a.t_min, "last annealing temperature (T_end) [energy units]", cli::positive());
    tool.add_int(*random, "--anneals", a.anneals, "number of temperatures, exponentially spaced", cli::at_least(1));
    tool.add_int(*random, "--sweeps", a.sweeps_per_anneal, "Monte Carlo sweeps (N trial moves each) per temperature",
                 cli::non_negative());
    tool.add_double(*random, "--epsilon", a.epsilon, "energy scale of the repulsive LJ-8 pair potential [energy units]",
                    cli::positive());
    tool.add_double(*random, "--cutoff", a.cutoff_sigmas, "pair cut-off [sigma = 2 r_v]", cli::positive());
    tool.add_double(*random, "--step", a.step_sigmas, "largest trial displacement per axis [sigma]", cli::positive());
    tool.add_seed_options(*random, o.seeding, "mesh");
    tool.add_common(*random, o.common, cli::Tool::kThreads);
    tool.add_output(*random, "--trace", o.trace, "also write temperature, acceptance and energy per anneal to this CSV");
    tool.add_output(*random, "-o,--output", o.output, "output OFF file ('-': stdout)");
    tool.add_common(*random, o.common, cli::Tool::kQuiet);

    auto* stats = app->add_subcommand("stats", "quality metrics (A.3) of closed triangle meshes, one CSV row per file");
    stats->add_option("meshes", o.inputs, "OFF files ('-': stdin)")->required();
    tool.declare_inputs(*stats, o.inputs);
    tool.add_output(*stats, "-o,--output", o.output, "output CSV file ('-': stdout)");
    tool.add_common(*stats, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    tool.parse(argc, argv);
    // A level is checked by the mesh it makes, before any of it is built: icosa at level 14
    // would be 671 million vertices (tens of GB), simple at level 14 is 49,154. A level outside
    // [1, 14] was reported by its range check, and has no vertex count.
    for (const auto& [sub, scheme] : schemes)
      if (sub->parsed() && o.level >= 1 && o.level <= spheremesh::kMaxSubdivisionLevel)
        tool.check(spheremesh::subdivision_vertex_count(scheme, o.level) <= kMaxMeshVertices, "--level",
                   fmt::format("level {} of {} makes {} vertices, more than {} (2^24)", o.level,
                               spheremesh::subdivision_name(scheme), spheremesh::subdivision_vertex_count(scheme, o.level),
                               kMaxMeshVertices));
    std::vector<std::uint64_t> seeds;
    if (random->parsed()) {
      tool.check(a.t_max >= a.t_min, "--tmax", fmt::format("must be at least --tmin ({} < {})", a.t_max, a.t_min));
      seeds = tool.seed_list(o.seeding);
      tool.check_seed_pattern(seeds.size(), "-o", o.output, "cell_{seed}.off");
      if (!o.trace.empty()) tool.check_seed_pattern(seeds.size(), "--trace", o.trace, "anneal_{seed}.csv");
      tool.check(!o.seeding.resume || o.output != "-", "--resume", "needs -o FILE (a mesh on stdout cannot be resumed)");
      if (tool.problem_count() == 0) tool.collect([&] { a.validate(); });
    }
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("rndmesh", argc, argv);

    for (const auto& [sub, scheme] : schemes)
      if (sub->parsed()) run_subdivision(o, scheme, provenance);
    if (random->parsed()) run_random(o, seeds, provenance);
    if (stats->parsed()) run_stats(o, provenance);
    return 0;
  });
}
