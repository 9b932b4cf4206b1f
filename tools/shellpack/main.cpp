// shellpack: packings of soft spheres and, later, of elastic shells (thesis 5.5.1, Ch. 4, App. B).
//   shellpack jam -N 50 --seed 7 -o jammed.xyz > jam.csv        one rattler-free jammed packing
//   shellpack jam -N 32 --seeds 1:100 > jam_stats.csv             many, in parallel
//   shellpack jam -N 20 -o - | shellpack structure -              the packing down a pipe (no CSV then)
//   shellpack structure jammed.xyz > rdf.csv                      g(r), Z, rattlers, contact forces
//   shellpack shell --mesh cell.off --model svk -E 25e6 --nu 0.333 -t 0.1 --pressure 2.5e5 -o inflated.off > inflate.csv
//   shellpack shell ... --walls 2.0 --squeeze 0.3 -o squeezed.off > plates.csv      one shell between two plates
//   shellpack analyze pack_*.off --rdf rdf.csv > structure.csv   Z, shapes, turgor, contact forces of shell packings
//   shellpack bench-mechanics sphere > sphere.csv                 the Appendix B benchmarks (Figs B.4-B.10)
//   shellpack compress jammed.xyz --mesh cell.off --phi 0.70:0.95:0.05 -o 'pack_{phi}.off' > compress.csv
//   shellpack compress --resume compress.chk > compress.csv         continue an interrupted compression
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "elasticity/benchmark_curves.hpp"
#include "io/atomic_output.hpp"
#include "packrun/jam_batch.hpp"
#include "packrun/shell_job.hpp"
#include "packrun/structure_batch.hpp"
#include "shell/mechanics_benchmarks.hpp"
#include "shell/styles.hpp"

#include "analyze_command.hpp"
#include "compress_command.hpp"
#include "volume_rule_option.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

using namespace cmp;
using shellpack::AnalyzeCommand;
using shellpack::CompressCommand;
using shellpack::with_checkpoint_args;

namespace {

struct Options {
  cli::CommonOptions common;
  cli::SeedOptions seeding;
  packrun::JamBatch jam;
  bool keep_rattlers = false, allow_hyperstatic = false;
  packrun::StructureBatch structure;
  packrun::ShellJob shell;
  double vertex_radius = 0, wall_gap = 0;
  bool list_models = false;
  shellpack::VolumeRuleOption volume_rule;
  // bench-mechanics
  std::string bench_case, bench_output = "-";
  bool bench_full = false, bench_analytic = false;
};

void check_jam(cli::Tool& tool, Options& o) {
  auto& p = o.jam.jamming;
  p.reject_rattlers = !o.keep_rattlers;
  p.require_isostatic = !o.allow_hyperstatic;
  tool.check(o.jam.spheres >= spheres::kMinJammingSpheres, "--spheres",
             fmt::format("N = {} is too small: a periodic rattler-free jammed packing needs N >= {} "
                         "(with fewer spheres each would touch two images of another)",
                         o.jam.spheres, spheres::kMinJammingSpheres));
  tool.check(p.fire.dt_max >= p.fire.dt, "--fire-dt-max", "must be at least --fire-dt");
  o.jam.seeds = tool.seed_list(o.seeding);
  o.jam.resume = o.seeding.resume;
  const std::string csv = packrun::jam_csv_path(o.jam);
  tool.check(!(o.jam.packing_output == "-" && csv == "-"), "--csv",
             "the packing already goes to stdout (-o -): write the CSV to a file");
  if (o.jam.resume) {
    tool.check(o.jam.packing_output.find("{seed}") != std::string::npos, "--resume",
               "needs -o with {seed} (one packing file per seed, e.g. -o 'jammed_{seed}.xyz')");
    tool.check(csv.empty() || csv.find("{seed}") != std::string::npos, "--resume",
               "needs --csv with {seed} (one table per seed, e.g. --csv 'jam_{seed}.csv'): a combined table "
               "would miss the skipped seeds");
  }
  if (tool.problem_count() == 0) tool.collect([&] { p.validate(); });
}

void check_structure(cli::Tool& tool, const packrun::StructureBatch& b) {
  tool.check(b.r_max > b.bin_width, "--rmax", "must exceed --bin");
  const int to_stdout = (b.output == "-") + (b.forces_output == "-") + (b.summary_output == "-");
  tool.check(to_stdout <= 1, "", "-o, --forces and --summary: at most one of them may be '-' (stdout)");
}

void check_shell(cli::Tool& tool, Options& o) {
  if (o.list_models) return;
  auto& job = o.shell;
  tool.check(!job.mesh_path.empty(), "--mesh", "is required (or --list-models)");
  auto& m = job.run.model;
  tool.collect("--model", [&] { shell::stretching_style(m.stretching); });
  if (m.bending == "none") m.bending.clear();
  if (!m.bending.empty()) tool.collect("--bending", [&] { shell::bending_style(m.bending); });
  tool.collect("--pressure-model", [&] { shell::pressure_style(m.pressure); });
  o.volume_rule.apply(tool, job.run.relax);
  m.contact.vertex_radius = o.vertex_radius > 0 ? o.vertex_radius : m.material.thickness;
  m.contact.youngs_modulus = m.material.youngs_modulus;
  m.contact.poisson_ratio = m.material.poisson_ratio;
  if (o.wall_gap > 0) job.run.wall_gap = o.wall_gap;
  tool.check(job.run.squeeze == 0 || job.run.wall_gap.has_value(), "--squeeze", "needs --walls");
  tool.check(!(job.mesh_output == "-" && job.csv == "-"), "--csv",
             "the mesh already goes to stdout (-o -): write the CSV to a file");
}

void run_bench_mechanics(const Options& o, const std::string& provenance) {
  io::AtomicOutput out(o.bench_output);
  if (o.bench_analytic)
    elasticity::write_csv(out.stream(), elasticity::analytic_curve(o.bench_case));
  else
    shell::run_mechanics_benchmark(o.bench_case, !o.bench_full, out.stream(), provenance, [&](const std::string& note) {
      if (!o.common.quiet) std::cerr << "shellpack: " << note << "\n";
    });
  out.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("shellpack", [&] {
    Options o;
    cli::Tool tool("shellpack", "Jammed packings of soft spheres, their structure, and pressurised elastic shells (thesis 5.5.1, Ch. 4, App. B).");
    auto* app = &tool.app();
    app->require_subcommand(1);
    tool.add_common(*app, o.common, cli::Tool::kQuiet);

    auto& p = o.jam.jamming;
    auto& f = p.fire;
    auto* jam = app->add_subcommand("jam", "jammed packing of N Hertzian spheres in a periodic cube (5.5.1); CSV row per packing");
    tool.add_int(*jam, "-N,--spheres", o.jam.spheres, fmt::format("number of spheres N (>= {})", spheres::kMinJammingSpheres))
        ->required();
    tool.add_seed_options(*jam, o.seeding, "packing");
    tool.add_common(*jam, o.common, cli::Tool::kThreads);
    jam->add_option("-o,--packing", o.jam.packing_output, "write the packing to this extended XYZ file (OVITO, ASE; '-': stdout); with --seeds, {seed} makes one file per seed, else every packing is one frame of this file, in seed order");
    jam->add_option("--csv", o.jam.csv_output,
                    "CSV of packing figures ('-': stdout; {seed}: one per seed) [default: stdout, none with -o -]");
    jam->add_flag("--timings", o.jam.timings, "add the wall time of each packing (`seconds`) to the CSV");
    tool.add_double(*jam, "--phi0", p.initial_volume_fraction, "volume fraction of the random start, psi_0", cli::open(0, 0.5));
    tool.add_double(*jam, "--eps-r", p.initial_step, "first relative radius step eps_r, halved at each reversal", cli::open(0, 0.5));
    tool.add_double(*jam, "--polydispersity", p.polydispersity,
                    "relative standard deviation of the radii (uniform sizes; 0: monodisperse as in the thesis)",
                    cli::closed(0, spheres::kMaxPolydispersity));
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
    structure->add_option("packings", o.structure.inputs, "extended XYZ packings (radius column, periodic Lattice; '-': stdin); frames pooled")
        ->required();
    structure->add_option("-o,--output", o.structure.output, "g(r) CSV ('-': stdout)");
    tool.add_double(*structure, "--bin", o.structure.bin_width, "g(r) bin width [mean diameters]", cli::positive());
    tool.add_double(*structure, "--rmax", o.structure.r_max,
                    "g(r) range [mean diameters]; beyond half the box every periodic image counts", cli::positive());
    structure->add_option("--forces", o.structure.forces_output, "write the contact force distribution P(f/<f>) to this CSV");
    tool.add_int(*structure, "--force-bins", o.structure.force_bins, "bins of the force distribution over [0, 4<f>)", cli::at_least(1));
    structure->add_option("--summary", o.structure.summary_output, "write one row per packing (Z, rattlers, pressure, force cv) to this CSV");
    tool.add_common(*structure, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto& run = o.shell.run;
    auto& model = run.model;
    model.pressure = "turgor";
    auto* sh = app->add_subcommand("shell", "one pressurised elastic shell on a triangle mesh, inflated and optionally "
                                            "squeezed between two plates (App. B); CSV row per load step");
    sh->add_option("--mesh", o.shell.mesh_path, "closed, outward-oriented triangle mesh (OFF; '-': stdin)");
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
    o.volume_rule.add(*sh);
    sh->add_option("-o,--output", o.shell.mesh_output, "write the relaxed mesh to this OFF ('-': stdout)");
    sh->add_option("--csv", o.shell.csv, "the table of load steps ('-': stdout)")->default_str("-");
    tool.add_common(*sh, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    AnalyzeCommand analyze_command;
    auto* analyze = analyze_command.add(tool, *app, o.common);

    auto* bench = app->add_subcommand("bench-mechanics", "an Appendix B benchmark as CSV, computed beside the analytic curve");
    bench->add_option("case", o.bench_case, "sphere, poisson, plate-point, plate-uniform, plate-large, plates-contact or buckling")
        ->required();
    bench->add_flag("--analytic", o.bench_analytic, "write the analytic reference curve of the case instead (lib/elasticity)");
    bench->add_flag("--full", o.bench_full, "the thesis's mesh sizes and every load (slower; the figures)");
    bench->add_option("-o,--output", o.bench_output, "CSV ('-': stdout)");
    tool.add_common(*bench, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    CompressCommand compress;
    auto* cp = compress.add(tool, *app, o.common);

    const auto full_args = with_checkpoint_args(argc, argv);
    std::vector<char*> full_argv;
    for (const auto& a : full_args) full_argv.push_back(const_cast<char*>(a.c_str()));
    tool.parse(static_cast<int>(full_argv.size()), full_argv.data());
    if (cp->parsed()) compress.check(tool, o.common, full_args);
    if (jam->parsed()) check_jam(tool, o);
    if (structure->parsed()) check_structure(tool, o.structure);
    if (sh->parsed()) check_shell(tool, o);
    if (analyze->parsed()) analyze_command.check(tool);
    if (bench->parsed()) tool.collect("case", [&] { shell::check_mechanics_benchmark(o.bench_case); });
    tool.finish_checks();
    cli::apply_threads(o.common);
    if (sh->parsed() && o.list_models) {
      shell::write_model_list(std::cout);
      return 0;
    }
    o.jam.quiet = o.structure.quiet = o.shell.quiet = o.common.quiet;
    const std::string provenance = cli::provenance("shellpack", argc, argv);
    if (jam->parsed()) packrun::run_jam_batch(o.jam, provenance);
    if (structure->parsed()) packrun::run_structure_batch(o.structure, provenance);
    if (sh->parsed()) packrun::run_shell_job(o.shell, provenance);
    if (analyze->parsed()) analyze_command.run(o.common.quiet, provenance);
    if (bench->parsed()) run_bench_mechanics(o, provenance);
    if (cp->parsed()) compress.run();
    return 0;
  });
}
