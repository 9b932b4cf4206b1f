// shellpack: packings of soft spheres and, later, of elastic shells (thesis 5.5.1, Ch. 4, App. B).
//   shellpack jam -N 50 --seed 7 -o jammed.xyz > jam.csv        one rattler-free jammed packing
//   shellpack jam -N 32 --seeds 1:100 > jam_stats.csv             many, in parallel
//   shellpack jam -N 20 -o - | shellpack structure -              the packing down a pipe (no CSV then)
//   shellpack structure jammed.xyz > rdf.csv                      g(r), Z, rattlers, contact forces
#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/xyz.hpp"
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
};

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
    cli::Tool tool("shellpack", "Jammed packings of soft spheres and their structure (thesis 5.5.1, Ch. 4).");
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

    tool.parse(argc, argv);
    std::vector<std::uint64_t> seeds;
    if (jam->parsed()) check_jam(tool, o, seeds);
    if (structure->parsed()) {
      tool.check(o.r_max > o.bin_width, "--rmax", "must exceed --bin");
      const int to_stdout = (o.output == "-") + (o.forces_output == "-") + (o.summary_output == "-");
      tool.check(to_stdout <= 1, "", "-o, --forces and --summary: at most one of them may be '-' (stdout)");
    }
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("shellpack", argc, argv);
    if (jam->parsed()) run_jam(o, seeds, provenance);
    if (structure->parsed()) run_structure(o, provenance);
    return 0;
  });
}
