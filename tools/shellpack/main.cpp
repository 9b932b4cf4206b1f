// shellpack: packings of soft spheres and, later, of elastic shells (thesis 5.5.1, Ch. 4, App. B).
//   shellpack jam -N 50 --seed 7 -o jammed.xyz > jam.csv        one rattler-free jammed packing
//   shellpack jam -N 32 --seeds 1:100 > jam_stats.csv             many, in parallel
//   shellpack jam -N 20 -o - | shellpack structure -              the packing down a pipe (no CSV then)
//   shellpack structure jammed.xyz > rdf.csv                      g(r), Z, rattlers, contact forces
//   shellpack shell --mesh cell.off --model svk -E 25e6 --nu 0.333 -t 0.1 --pressure 2.5e5 -o inflated.off > inflate.csv
//   shellpack shell ... --walls 2.0 --squeeze 0.3 -o squeezed.off > plates.csv      one shell between two plates
//   shellpack bench-mechanics sphere > sphere.csv                 the Appendix B benchmarks (Figs B.4-B.10)
#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "elasticity/benchmark_curves.hpp"
#include "io/off.hpp"
#include "io/xyz.hpp"
#include "shell/mechanics_benchmarks.hpp"
#include "shell/shell_run.hpp"
#include "shell/styles.hpp"
#include "spheres/jamming.hpp"
#include "spheres/jamming_report.hpp"
#include "spheres/structure_report.hpp"

#include <fmt/format.h>

#include <omp.h>

#include <atomic>
#include <memory>
#include <iostream>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  cli::SeedOptions seeding;
  // jam
  int spheres = 0;
  std::string packing_output;  // XYZ; {seed} with --seeds
  std::string csv_output;      // empty: stdout, unless the packing goes there
  bool timings = false;
  spheres::JammingParameters jamming;
  bool keep_rattlers = false, allow_hyperstatic = false;
  // structure
  std::vector<std::string> inputs;
  double bin_width = 0.01, r_max = 3.0;
  int force_bins = 40;
  std::string forces_output, summary_output;
  std::string output = "-";
  // shell
  shell::ShellRunOptions run;
  std::string mesh_path, mesh_output, shell_csv = "-", vertex_radius_text;
  double vertex_radius = 0, wall_gap = 0;
  bool list_models = false;
  // bench-mechanics
  std::string bench_case;
  bool bench_full = false, bench_analytic = false;
};

// --list-models: every registered style of every kind, from the tables the options read.
void list_models() {
  const auto print = [](const char* kind, const auto& table) {
    for (const auto& s : table) std::cout << kind << "," << s.name << ",\"" << s.description << "\"\n";
  };
  std::cout << "kind,name,description\n";
  print("stretching", shell::stretching_styles());
  print("bending", shell::bending_styles());
  print("pressure", shell::pressure_styles());
  print("contact", shell::contact_styles());
}

void check_shell(cli::Tool& tool, Options& o) {
  if (o.list_models) return;
  tool.check(!o.mesh_path.empty(), "--mesh", "is required (or --list-models)");
  auto& m = o.run.model;
  tool.collect("--model", [&] { shell::stretching_style(m.stretching); });
  if (m.bending == "none") m.bending.clear();
  if (!m.bending.empty()) tool.collect("--bending", [&] { shell::bending_style(m.bending); });
  tool.collect("--pressure-model", [&] { shell::pressure_style(m.pressure); });
  m.contact.vertex_radius = o.vertex_radius > 0 ? o.vertex_radius : m.material.thickness;
  m.contact.youngs_modulus = m.material.youngs_modulus;
  m.contact.poisson_ratio = m.material.poisson_ratio;
  if (o.wall_gap > 0) o.run.wall_gap = o.wall_gap;
  tool.check(o.run.squeeze == 0 || o.run.wall_gap.has_value(), "--squeeze", "needs --walls");
  tool.check(!(o.mesh_output == "-" && o.shell_csv == "-"), "--csv",
             "the mesh already goes to stdout (-o -): write the CSV to a file");
}

void run_shell_command(const Options& o, const std::string& provenance) {
  // Everything about the input is checked before any work.
  const auto off = io::read_off(o.mesh_path);
  mesh::TriMesh rest{off.V, off.F};
  shell::check_closed_shell_mesh(rest, o.mesh_path);
  if (o.run.wall_gap) shell::check_walls_clear(rest, *o.run.wall_gap, o.run.model.contact.vertex_radius);
  std::unique_ptr<io::AtomicOutput> csv_out;
  if (!o.shell_csv.empty()) csv_out = std::make_unique<io::AtomicOutput>(o.shell_csv);
  const int total = o.run.pressure_steps + (o.run.wall_gap ? o.run.squeeze_steps + 1 : 0);
  cli::ProgressBar bar("relaxing", static_cast<double>(total), o.common.quiet);
  const auto result = shell::run_shell(
      rest, o.run,
      [&](const shell::ShellRunRow& row) {
        bar.update(static_cast<double>(row.step + 1));
        if (!row.relax.converged())
          std::cerr << "shellpack: warning: step " << row.step << " stopped by " << shell::relax_stop_name(row.relax.stop)
                    << " at residual " << row.relax.residual << "\n";
      },
      {});
  bar.finish();
  if (csv_out) shell::write_shell_table(csv_out->stream(), result, o.run, provenance);
  if (!o.mesh_output.empty()) {
    mesh::VertexMatrix V = Eigen::Map<const mesh::VertexMatrix>(result.final_state.data(), rest.V.rows(), 3);
    io::write_off(o.mesh_output, V, rest.F, {provenance});
  }
  if (csv_out) csv_out->commit();
  if (!o.common.quiet && !result.rows.empty()) {
    const auto& last = result.rows.back();
    std::cerr << "shellpack: " << result.rows.size() << " steps; last: Pi " << last.observables.turgor << ", volume "
              << last.observables.volume << ", " << shell::relax_stop_name(last.relax.stop) << " (residual "
              << last.relax.residual << ")\n";
  }
}

void run_bench_mechanics(const Options& o, const std::string& provenance) {
  io::AtomicOutput out(o.output);
  if (o.bench_analytic) {
    elasticity::write_csv(out.stream(), elasticity::analytic_curve(o.bench_case));
    out.commit();
    return;
  }
  shell::run_mechanics_benchmark(o.bench_case, !o.bench_full, out.stream(), provenance,
                                 [&](const std::string& note) {
                                   if (!o.common.quiet) std::cerr << "shellpack: " << note << "\n";
                                 });
  out.commit();
}

// Where jam's CSV goes: --csv, or stdout when the packing does not go there (`-o -` alone
// writes only the packing, so that `shellpack jam -o - | shellpack structure -` works).
std::string jam_csv_path(const Options& o) {
  if (!o.csv_output.empty()) return o.csv_output;
  return o.packing_output == "-" ? "" : "-";
}

void check_jam(cli::Tool& tool, Options& o, std::vector<std::uint64_t>& seeds) {
  auto& p = o.jamming;
  p.reject_rattlers = !o.keep_rattlers;
  p.require_isostatic = !o.allow_hyperstatic;
  tool.check(o.spheres >= spheres::kMinJammingSpheres, "--spheres",
             fmt::format("N = {} is too small: a periodic rattler-free jammed packing needs N >= {} "
                         "(with fewer spheres each would touch two images of another)",
                         o.spheres, spheres::kMinJammingSpheres));
  tool.check(p.fire.dt_max >= p.fire.dt, "--fire-dt-max", "must be at least --fire-dt");
  seeds = tool.seed_list(o.seeding);
  // -o with {seed}: one file per seed; without (a file or '-'): every packing as one frame of a
  // single extended XYZ, in seed order (percolate reads every frame).
  const std::string csv = jam_csv_path(o);
  tool.check(!(o.packing_output == "-" && csv == "-"), "--csv",
             "the packing already goes to stdout (-o -): write the CSV to a file");
  if (o.seeding.resume) {
    tool.check(o.packing_output.find("{seed}") != std::string::npos, "--resume",
               "needs -o with {seed} (one packing file per seed, e.g. -o 'jammed_{seed}.xyz')");
    tool.check(csv.empty() || csv.find("{seed}") != std::string::npos, "--resume",
               "needs --csv with {seed} (one table per seed, e.g. --csv 'jam_{seed}.csv'): a combined table "
               "would miss the skipped seeds");
  }
  if (tool.problem_count() == 0) tool.collect([&] { p.validate(); });
}

void run_jam(const Options& o, const std::vector<std::uint64_t>& all_seeds, const std::string& provenance) {
  const auto& p = o.jamming;
  const std::string csv = jam_csv_path(o);
  const bool csv_per_seed = csv.find("{seed}") != std::string::npos;
  const bool packing_per_seed = o.packing_output.find("{seed}") != std::string::npos;
  const auto seed_outputs = [&](std::uint64_t s) {
    std::vector<std::string> out;
    if (packing_per_seed) out.push_back(cli::expand_pattern(o.packing_output, "seed", std::to_string(s)));
    if (csv_per_seed) out.push_back(cli::expand_pattern(csv, "seed", std::to_string(s)));
    return out;
  };
  std::vector<std::uint64_t> seeds;
  for (const auto s : all_seeds)
    if (!(o.seeding.resume && cli::outputs_complete(seed_outputs(s)))) seeds.push_back(s);
  if (seeds.size() < all_seeds.size() && !o.common.quiet)
    std::cerr << "shellpack: --resume: " << all_seeds.size() - seeds.size() << " of " << all_seeds.size()
              << " seeds already done\n";
  // A warning, not chatter: said under -q too.
  const auto rarity = spheres::acceptance_warning(o.spheres, p);
  if (!rarity.empty()) std::cerr << "shellpack: warning: " << rarity << "\n";

  const long n = static_cast<long>(seeds.size());
  std::vector<spheres::JammingResult> results(static_cast<std::size_t>(n));
  cli::ProgressBar bar("jamming", static_cast<double>(n), o.common.quiet);
  std::atomic<long> done{0};
  // Tries and rejections so far, over every seed, for the bar's note.
  spheres::JammingProgressNote note(static_cast<std::size_t>(n));
  parallel_for_each_job(n, [&](long k) {
    results[k] = spheres::jam_spheres(o.spheres, seeds[k], p, [&](const spheres::JammingProgressInfo& info) {
      if (bar.enabled())
        if (auto text = note.update(static_cast<std::size_t>(k), info); !text.empty()) bar.set_note(text, true);
      return true;
    });
    const std::string seed = std::to_string(seeds[k]);
    if (packing_per_seed)
      io::write_xyz(cli::expand_pattern(o.packing_output, "seed", seed),
                    {spheres::jammed_frame(results[k], seeds[k], provenance, p.material)});
    if (csv_per_seed) {
      io::AtomicOutput out(cli::expand_pattern(csv, "seed", seed));
      spheres::write_jamming_table(out.stream(), {results[k]}, {seeds[k]}, p, provenance, o.timings);
      out.commit();
    }
    const long finished = ++done;
    bar.update(static_cast<double>(finished));
  });
  bar.finish();
  if (!o.packing_output.empty() && !packing_per_seed) {
    std::vector<io::XyzFrame> frames;
    for (long k = 0; k < n; ++k) frames.push_back(spheres::jammed_frame(results[k], seeds[k], provenance, p.material));
    io::write_xyz(o.packing_output, frames);
  }
  if (!csv.empty() && !csv_per_seed) {
    io::AtomicOutput out(csv);
    spheres::write_jamming_table(out.stream(), results, seeds, p, provenance, o.timings);
    out.commit();
  }
  if (!o.common.quiet && n == 1) std::cerr << "shellpack: " << spheres::jamming_summary(results.front()) << "\n";
  if (!o.common.quiet && n > 1) std::cerr << "shellpack: " << spheres::jamming_batch_summary(results) << "\n";
}

void run_structure(const Options& o, const std::string& provenance) {
  // Read every file first: a bad one stops the run before anything is written.
  std::vector<spheres::SpherePacking> packings;
  std::vector<std::string> labels;
  for (const auto& path : o.inputs) {
    auto frames = spheres::read_sphere_packings(path);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      labels.push_back(frames.size() > 1 ? fmt::format("{}#{}", path, f) : path);
      packings.push_back(std::move(frames[f]));
    }
  }
  const auto rdf = spheres::radial_distribution(packings, o.bin_width, o.r_max);
  std::vector<spheres::ContactStatistics> stats(packings.size());
  parallel_for_each_job(static_cast<long>(packings.size()), [&](long k) { stats[k] = spheres::contact_statistics(packings[k]); });
  const auto pooled = spheres::pool_contacts(stats);

  io::AtomicOutput out(o.output);
  std::unique_ptr<io::AtomicOutput> forces_out, summary_out;
  if (!o.forces_output.empty()) forces_out = std::make_unique<io::AtomicOutput>(o.forces_output);
  if (!o.summary_output.empty()) summary_out = std::make_unique<io::AtomicOutput>(o.summary_output);
  spheres::write_rdf_table(out.stream(), rdf, pooled, packings.size(), provenance);
  if (forces_out) spheres::write_force_distribution_table(forces_out->stream(), pooled, o.force_bins, provenance);
  if (summary_out) spheres::write_contact_summary_table(summary_out->stream(), labels, stats, provenance);
  out.commit();
  if (forces_out) forces_out->commit();
  if (summary_out) summary_out->commit();
  if (!o.common.quiet)
    for (std::size_t k = 0; k < stats.size(); ++k)
      std::cerr << "shellpack: " << spheres::contact_summary(labels[k], stats[k]) << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("shellpack", [&] {
    Options o;
    cli::Tool tool("shellpack", "Jammed packings of soft spheres, their structure, and pressurised elastic shells (thesis 5.5.1, Ch. 4, App. B).");
    auto* app = &tool.app();
    app->require_subcommand(1);
    tool.add_common(*app, o.common, cli::Tool::kQuiet);

    auto& p = o.jamming;
    auto& f = p.fire;
    auto* jam = app->add_subcommand("jam", "jammed packing of N Hertzian spheres in a periodic cube (5.5.1); CSV row per packing");
    tool.add_int(*jam, "-N,--spheres", o.spheres, fmt::format("number of spheres N (>= {})", spheres::kMinJammingSpheres))
        ->required();
    tool.add_seed_options(*jam, o.seeding, "packing");
    tool.add_common(*jam, o.common, cli::Tool::kThreads);
    jam->add_option("-o,--packing", o.packing_output, "write the packing to this extended XYZ file (OVITO, ASE; '-': stdout); with --seeds, {seed} makes one file per seed, else every packing is one frame of this file, in seed order");
    jam->add_option("--csv", o.csv_output,
                    "CSV of packing figures ('-': stdout; {seed}: one per seed) [default: stdout, none with -o -]");
    jam->add_flag("--timings", o.timings, "add the wall time of each packing (`seconds`) to the CSV");
    tool.add_double(*jam, "--phi0", p.initial_volume_fraction, "volume fraction of the random start, psi_0", cli::open(0, 0.5));
    tool.add_double(*jam, "--eps-r", p.initial_step, "first relative radius step eps_r, halved at each reversal", cli::open(0, 0.5));
    tool.add_double(*jam, "--pmin", p.min_pressure, "P_min [E]: stop when P_min < P < 2 P_min", cli::positive());
    tool.add_double(*jam, "--youngs-modulus", p.material.youngs_modulus, "Young's modulus E of the spheres [pressure units]",
                    cli::positive());
    tool.add_double(*jam, "--poisson-ratio", p.material.poisson_ratio, "Poisson's ratio nu of the spheres", cli::open(-1, 1));
    tool.add_double(*jam, "--ftol", f.force_tolerance, "FIRE stops when max_i |f_i| <= this [E d^2]; thesis 1e-15",
                    cli::non_negative());
    tool.add_long(*jam, "--fire-max-iterations", f.max_iterations,
                  "FIRE iteration cap per minimisation (a try that hits it is rejected)", cli::at_least(1));
    tool.add_long(*jam, "--step-fire-cap", p.step_iteration_cap,
                  "FIRE iterations after each size change before moving on unrelaxed (0: relax every step; "
                  "the final packing is always relaxed to --ftol)",
                  cli::non_negative());
    tool.add_double(*jam, "--fire-dt", f.dt, "FIRE initial time step dt_FIRE", cli::positive());
    tool.add_double(*jam, "--fire-dt-max", f.dt_max, "FIRE largest time step dt_FIRE^max", cli::positive());
    tool.add_double(*jam, "--fire-alpha", f.alpha_start, "FIRE initial mixing alpha_FIRE", cli::open(0, 1));
    tool.add_int(*jam, "--fire-nmin", f.n_min, "FIRE steps with P > 0 before dt grows, N_min", cli::non_negative());
    tool.add_double(*jam, "--fire-f-alpha", f.f_alpha, "FIRE alpha shrink factor f_alpha", cli::left_open(0, 1));
    tool.add_double(*jam, "--fire-f-inc", f.f_inc, "FIRE time step growth f_inc", cli::at_least(1));
    tool.add_double(*jam, "--fire-f-dec", f.f_dec, "FIRE time step cut f_dec", cli::open(0, 1));
    tool.add_int(*jam, "--max-tries", p.max_tries, "random starts per packing before giving up (exit 1)", cli::at_least(1));
    jam->add_flag("--keep-rattlers", o.keep_rattlers, "accept packings with rattlers (the thesis rejects them)");
    jam->add_flag("--allow-hyperstatic", o.allow_hyperstatic,
                  "accept rattler-free packings with more than 3N - 2 contacts (crystallites; the thesis's literal rule)");
    tool.add_common(*jam, o.common, cli::Tool::kQuiet);

    auto* structure = app->add_subcommand("structure", "g(r), contact number, rattlers and contact forces of sphere packings");
    structure->add_option("packings", o.inputs, "extended XYZ packings (radius column, periodic Lattice; '-': stdin); frames pooled")
        ->required();
    structure->add_option("-o,--output", o.output, "g(r) CSV ('-': stdout)");
    tool.add_double(*structure, "--bin", o.bin_width, "g(r) bin width [mean diameters]", cli::positive());
    tool.add_double(*structure, "--rmax", o.r_max,
                    "g(r) range [mean diameters]; beyond half the box every periodic image counts", cli::positive());
    structure->add_option("--forces", o.forces_output, "write the contact force distribution P(f/<f>) to this CSV");
    tool.add_int(*structure, "--force-bins", o.force_bins, "bins of the force distribution over [0, 4<f>)", cli::at_least(1));
    structure->add_option("--summary", o.summary_output, "write one row per packing (Z, rattlers, pressure, force cv) to this CSV");
    tool.add_common(*structure, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto& run = o.run;
    auto& model = run.model;
    model.pressure = "turgor";
    auto* sh = app->add_subcommand("shell", "one pressurised elastic shell on a triangle mesh, inflated and optionally "
                                            "squeezed between two plates (App. B); CSV row per load step");
    sh->add_option("--mesh", o.mesh_path, "closed, outward-oriented triangle mesh (OFF; '-': stdin)");
    sh->add_flag("--list-models", o.list_models, "list the registered stretching, bending, pressure and contact models (CSV) and exit");
    sh->add_option("--model", model.stretching, "stretching model (--list-models)")->default_str("svk");
    sh->add_option("--bending", model.bending, "bending model, or none (a membrane)")->default_str("none");
    sh->add_option("--pressure-model", model.pressure, "turgor (constant Pi) or volume (inflate, then hold the volume)")
        ->default_str("turgor");
    tool.add_double(*sh, "-E,--youngs-modulus", model.material.youngs_modulus, "Young's modulus E [P: any pressure unit]",
                    cli::positive());
    tool.add_double(*sh, "--nu,--poisson-ratio", model.material.poisson_ratio, "Poisson's ratio nu",
                    cli::left_open(-1, 0.5));
    tool.add_double(*sh, "-t,--thickness", model.material.thickness, "wall thickness t [u: the mesh's length unit]",
                    cli::positive());
    tool.add_double(*sh, "--pressure", run.pressure, "turgor Pi to inflate to [P]");
    tool.add_int(*sh, "--steps", run.pressure_steps, "inflation load steps (one CSV row each)", cli::at_least(1));
    tool.add_double(*sh, "--walls", o.wall_gap, "put two plates this far apart (normal z, centred on the mesh) [u]",
                    cli::non_negative());
    tool.add_double(*sh, "--squeeze", run.squeeze, "reduce the plate gap by this fraction after inflating",
                    cli::right_open(0, 1));
    tool.add_int(*sh, "--squeeze-steps", run.squeeze_steps, "squeeze steps (one CSV row each)", cli::at_least(1));
    tool.add_double(*sh, "--vertex-radius", o.vertex_radius, "Hertz vertex radius R_v [u] (default: t)", cli::non_negative());
    tool.add_double(*sh, "--wall-modulus", model.contact.wall_modulus, "Young's modulus of the plates [P] (default: rigid)",
                    cli::positive());
    tool.add_double(*sh, "--ftol", run.relax.relative_tolerance,
                    "FIRE stops when max_i |f_i| <= this * E t a (a: mean rest edge length)", cli::positive());
    tool.add_long(*sh, "--fire-max-iterations", run.relax.fire.max_iterations, "FIRE iteration cap per relaxation",
                  cli::at_least(1));
    sh->add_option("-o,--output", o.mesh_output, "write the relaxed mesh to this OFF ('-': stdout)");
    sh->add_option("--csv", o.shell_csv, "the table of load steps ('-': stdout)")->default_str("-");
    tool.add_common(*sh, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto* bench = app->add_subcommand("bench-mechanics", "an Appendix B benchmark as CSV, computed beside the analytic curve");
    bench->add_option("case", o.bench_case, "sphere, poisson, plate-point, plate-uniform, plate-large, plates-contact or buckling")
        ->required();
    bench->add_flag("--analytic", o.bench_analytic, "write the analytic reference curve of the case instead (lib/elasticity)");
    bench->add_flag("--full", o.bench_full, "the thesis's mesh sizes and every load (slower; the figures)");
    bench->add_option("-o,--output", o.output, "CSV ('-': stdout)");
    tool.add_common(*bench, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    tool.parse(argc, argv);
    std::vector<std::uint64_t> seeds;
    if (jam->parsed()) check_jam(tool, o, seeds);
    if (structure->parsed()) {
      tool.check(o.r_max > o.bin_width, "--rmax", "must exceed --bin");
      const int to_stdout = (o.output == "-") + (o.forces_output == "-") + (o.summary_output == "-");
      tool.check(to_stdout <= 1, "", "-o, --forces and --summary: at most one of them may be '-' (stdout)");
    }
    if (sh->parsed()) check_shell(tool, o);
    if (bench->parsed()) tool.collect("case", [&] { shell::check_mechanics_benchmark(o.bench_case); });
    tool.finish_checks();
    cli::apply_threads(o.common);
    if (sh->parsed() && o.list_models) {
      list_models();
      return 0;
    }
    const std::string provenance = cli::provenance("shellpack", argc, argv);
    if (jam->parsed()) run_jam(o, seeds, provenance);
    if (structure->parsed()) run_structure(o, provenance);
    if (sh->parsed()) run_shell_command(o, provenance);
    if (bench->parsed()) run_bench_mechanics(o, provenance);
    return 0;
  });
}
