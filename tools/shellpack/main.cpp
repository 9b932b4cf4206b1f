// shellpack: packings of soft spheres and, later, of elastic shells (thesis 5.5.1, Ch. 4, App. B).
//   shellpack jam -N 50 --seed 7 -o jammed.xyz > jam.csv        one rattler-free jammed packing
//   shellpack jam -N 32 --seeds 1:100 > jam_stats.csv             many, in parallel
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
  // jam
  int spheres = 0;
  std::string seeds;
  std::string packing_output;  // XYZ; {seed} with --seeds
  spheres::JammingParameters jamming;
  bool keep_rattlers = false, allow_hyperstatic = false;
  // structure
  std::vector<std::string> inputs;
  double bin_width = 0.01, r_max = 3.0;
  int force_bins = 40;
  std::string forces_output, summary_output;
  std::string output = "-";
};

void run_jam(Options& o, const std::string& provenance) {
  auto& p = o.jamming;
  p.reject_rattlers = !o.keep_rattlers;
  p.require_isostatic = !o.allow_hyperstatic;
  cli::OptionChecks checks;
  checks.require(o.spheres >= spheres::kMinJammingSpheres,
                 fmt::format("-N {} is too small: a periodic rattler-free jammed packing needs N >= {} "
                             "(with fewer spheres each would touch two images of another)",
                             o.spheres, spheres::kMinJammingSpheres));
  const auto seeds = o.seeds.empty() ? std::vector<std::uint64_t>{o.common.seed} : cli::parse_seed_range(o.seeds);
  checks.require(seeds.size() == 1 || o.packing_output.empty() || o.packing_output.find("{seed}") != std::string::npos,
                 "-o must contain {seed} when --seeds names several seeds, e.g. -o 'jammed_{seed}.xyz'");
  checks.throw_if_any();
  p.validate();

  const long n = static_cast<long>(seeds.size());
  std::vector<spheres::JammingResult> results(static_cast<std::size_t>(n));
  cli::ProgressBar bar("jamming", static_cast<double>(n), o.common.quiet);
  std::atomic<long> done{0};
  parallel_for_each_job(n, [&](long k) {
    results[k] = spheres::jam_spheres(o.spheres, seeds[k], p);
    if (!o.packing_output.empty())
      io::write_xyz(cli::expand_pattern(o.packing_output, "seed", std::to_string(seeds[k])),
                    {spheres::jammed_frame(results[k], seeds[k], provenance, p.material)});
    const long finished = ++done;
    if (omp_get_thread_num() == 0) bar.update(static_cast<double>(finished));
  });

  io::AtomicOutput out(o.output);
  spheres::write_jamming_table(out.stream(), results, seeds, p, provenance);
  out.commit();
  if (!o.common.quiet && n == 1) std::cerr << "shellpack: " << spheres::jamming_summary(results.front()) << "\n";
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
    auto app = cli::make_app("shellpack", "Jammed packings of soft spheres and their structure (thesis 5.5.1, Ch. 4).");
    app->require_subcommand(1);
    cli::add_quiet_option(*app, o.common);

    auto& p = o.jamming;
    auto& f = p.fire;
    auto* jam = app->add_subcommand("jam", "jammed packing of N Hertzian spheres in a periodic cube (5.5.1); CSV row per packing");
    jam->add_option("-N,--spheres", o.spheres, "number of spheres N (>= 10)")->required();
    auto* seed = jam->add_option("--seed", o.common.seed, "seed of the random start; same seed, same packing");
    jam->add_option("--seeds", o.seeds, "FIRST:LAST: one packing per seed, in parallel; -o needs {seed}")->excludes(seed);
    cli::add_threads_option(*jam, o.common);
    jam->add_option("-o,--packing", o.packing_output, "write the packing to this extended XYZ file (OVITO, ASE)");
    jam->add_option("--csv", o.output, "CSV of packing figures ('-': stdout)");
    jam->add_option("--phi0", p.initial_volume_fraction, "volume fraction of the random start, psi_0");
    jam->add_option("--eps-r", p.initial_step, "first relative radius step eps_r, halved at each reversal");
    jam->add_option("--pmin", p.min_pressure, "P_min [E]: stop when P_min < P < 2 P_min");
    jam->add_option("--youngs-modulus", p.material.youngs_modulus, "Young's modulus E of the spheres [pressure units]");
    jam->add_option("--poisson-ratio", p.material.poisson_ratio, "Poisson's ratio nu of the spheres");
    jam->add_option("--ftol", f.force_tolerance, "FIRE stops when max_i |f_i| <= this [E d^2]; thesis 1e-15");
    jam->add_option("--fire-max-iterations", f.max_iterations, "FIRE iteration cap per minimisation (a try that hits it is rejected)");
    jam->add_option("--step-fire-cap", p.step_iteration_cap,
                    "FIRE iterations after each size change before moving on unrelaxed (0: relax every step; "
                    "the final packing is always relaxed to --ftol)");
    jam->add_option("--fire-dt", f.dt, "FIRE initial time step dt_FIRE");
    jam->add_option("--fire-dt-max", f.dt_max, "FIRE largest time step dt_FIRE^max");
    jam->add_option("--fire-alpha", f.alpha_start, "FIRE initial mixing alpha_FIRE");
    jam->add_option("--fire-nmin", f.n_min, "FIRE steps with P > 0 before dt grows, N_min");
    jam->add_option("--fire-f-alpha", f.f_alpha, "FIRE alpha shrink factor f_alpha");
    jam->add_option("--fire-f-inc", f.f_inc, "FIRE time step growth f_inc");
    jam->add_option("--fire-f-dec", f.f_dec, "FIRE time step cut f_dec");
    jam->add_option("--max-tries", p.max_tries, "random starts per packing before giving up (exit 1)");
    jam->add_flag("--keep-rattlers", o.keep_rattlers, "accept packings with rattlers (the thesis rejects them)");
    jam->add_flag("--allow-hyperstatic", o.allow_hyperstatic,
                  "accept rattler-free packings with more than 3N - 2 contacts (crystallites; the thesis's literal rule)");
    cli::add_quiet_option(*jam, o.common);

    auto* structure = app->add_subcommand("structure", "g(r), contact number, rattlers and contact forces of sphere packings");
    structure->add_option("packings", o.inputs, "extended XYZ packings (radius column, periodic Lattice); frames pooled")->required();
    structure->add_option("-o,--output", o.output, "g(r) CSV ('-': stdout)");
    structure->add_option("--bin", o.bin_width, "g(r) bin width [mean diameters]");
    structure->add_option("--rmax", o.r_max, "g(r) range [mean diameters]; beyond half the box every periodic image counts");
    structure->add_option("--forces", o.forces_output, "write the contact force distribution P(f/<f>) to this CSV");
    structure->add_option("--force-bins", o.force_bins, "bins of the force distribution over [0, 4<f>)");
    structure->add_option("--summary", o.summary_output, "write one row per packing (Z, rattlers, pressure, force cv) to this CSV");
    cli::add_threads_option(*structure, o.common);
    cli::add_quiet_option(*structure, o.common);

    cli::parse(*app, argc, argv);
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("shellpack", argc, argv);
    if (jam->parsed()) run_jam(o, provenance);
    if (structure->parsed()) {
      cli::OptionChecks checks;
      checks.require(o.bin_width > 0, "--bin must be positive");
      checks.require(o.r_max > o.bin_width, "--rmax must exceed --bin");
      checks.require(o.force_bins >= 1, "--force-bins must be at least 1");
      checks.throw_if_any();
      run_structure(o, provenance);
    }
    return 0;
  });
}
