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
#include "io/csv.hpp"
#include "io/xyz.hpp"
#include "io/xyz_frame.hpp"
#include "spheres/hertz_spheres.hpp"
#include "spheres/jamming.hpp"
#include "spheres/rattlers.hpp"
#include "spheres/structure.hpp"

#include <fmt/format.h>

#include <omp.h>

#include <atomic>
#include <memory>
#include <iostream>

using namespace cmp;
using io::format_number;

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

// The packing with its contact counts and the protocol's figures, as OVITO/ASE read it.
io::XyzFrame jammed_frame(const spheres::JammingResult& r, std::uint64_t seed, const std::string& provenance,
                          const spheres::HertzMaterial& material) {
  auto frame = spheres::packing_to_frame(r.packing);
  spheres::HertzSpheres system(r.packing.box, r.packing.radii, material, 0.0);
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(r.packing.positions.data(), 3L * r.packing.size());
  frame.set_integer_column("contacts", spheres::contact_counts(r.packing.size(), system.evaluate(x).contacts));
  frame.set_info("tool", provenance);
  frame.set_info("seed", std::to_string(seed));
  frame.set_info("phi", format_number(r.packing.volume_fraction()));
  frame.set_info("Z", format_number(r.contact_number()));
  frame.set_info("contacts", std::to_string(r.contacts));
  frame.set_info("pressure_E", format_number(r.pressure));
  frame.set_info("max_force_E", format_number(r.max_force));
  frame.set_info("diameter", format_number(r.packing.mean_diameter()));
  return frame;
}

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
                    {jammed_frame(results[k], seeds[k], provenance, p.material)});
    const long finished = ++done;
    if (omp_get_thread_num() == 0) bar.update(static_cast<double>(finished));
  });

  io::AtomicOutput out(o.output);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  csv.meta("E", format_number(p.material.youngs_modulus));
  csv.meta("nu", format_number(p.material.poisson_ratio));
  csv.meta("P_min", format_number(p.min_pressure));
  csv.meta("eps_r", format_number(p.initial_step));
  csv.meta("phi_0", format_number(p.initial_volume_fraction));
  csv.meta("force_tolerance", format_number(p.fire.force_tolerance));
  csv.meta("units", "pressure in E, energy in E d^3 (d: jammed diameter); max_force in the packing file's units "
                    "(E times length^2, lengths such that d is about 1), the units of --ftol");
  csv.header({"seed", "N", "phi_J", "Z", "contacts", "contacts_isostatic", "pressure_E", "energy_Ed3", "max_force",
              "box_side_d", "fire_iterations", "size_changes", "rejected_tries", "rejected_rattlers",
              "rejected_not_isostatic", "seconds"});
  for (long k = 0; k < n; ++k) {
    const auto& r = results[k];
    const double d = r.packing.mean_diameter();
    csv.row({std::to_string(seeds[k]), std::to_string(o.spheres), format_number(r.packing.volume_fraction()),
             format_number(r.contact_number()), std::to_string(r.contacts),
             std::to_string(spheres::isostatic_contacts(o.spheres)), format_number(r.pressure),
             format_number(r.energy / (d * d * d)), format_number(r.max_force),
             format_number(r.packing.box[0] / d), std::to_string(r.fire_iterations), std::to_string(r.size_changes),
             std::to_string(r.rejected_tries), std::to_string(r.rejected_for_rattlers),
             std::to_string(r.rejected_not_isostatic), fmt::format("{:.4f}", r.seconds)});
  }
  out.commit();
  if (!o.common.quiet && n == 1) {
    const auto& r = results.front();
    std::cerr << fmt::format("shellpack: N = {}: phi_J = {:.5f}, Z = {:.4f} ({} contacts, isostatic {}), P = {:.3g} E, "
                             "max|F| = {:.2g} E, {} FIRE iterations, {} rejected tries, {:.2f} s\n",
                             o.spheres, r.packing.volume_fraction(), r.contact_number(), r.contacts,
                             spheres::isostatic_contacts(o.spheres), r.pressure, r.max_force, r.fire_iterations,
                             r.rejected_tries, r.seconds);
  }
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
  std::vector<double> all_forces;
  double z_sum = 0;
  long rattlers = 0;
  for (const auto& s : stats) {
    // Forces relative to their packing's mean, so that packings at different pressures pool.
    for (double f : s.forces) all_forces.push_back(f / s.mean_force);
    z_sum += s.contact_number;
    rattlers += s.rattlers;
  }
  double cv = 0;
  if (!all_forces.empty()) {
    double m = 0, v = 0;
    for (double f : all_forces) m += f;
    m /= all_forces.size();
    for (double f : all_forces) v += (f - m) * (f - m);
    cv = std::sqrt(v / all_forces.size()) / m;
  }

  io::AtomicOutput out(o.output);
  std::unique_ptr<io::AtomicOutput> forces_out, summary_out;
  if (!o.forces_output.empty()) forces_out = std::make_unique<io::AtomicOutput>(o.forces_output);
  if (!o.summary_output.empty()) summary_out = std::make_unique<io::AtomicOutput>(o.summary_output);
  {
    io::CsvWriter csv(out.stream());
    csv.meta("provenance", provenance);
    csv.meta("packings", std::to_string(packings.size()));
    csv.meta("Z_mean", format_number(z_sum / packings.size()));
    csv.meta("rattlers", std::to_string(rattlers));
    csv.meta("force_cv", format_number(cv));
    csv.meta("units", "r in mean diameters; g normalised to the ideal gas of the same density");
    csv.header({"r_d", "g", "pairs"});
    for (std::size_t b = 0; b < rdf.r.size(); ++b)
      csv.row({format_number(rdf.r[b]), format_number(rdf.g[b]), std::to_string(rdf.pair_counts[b])});
  }
  if (forces_out) {
    const auto h = spheres::normalised_histogram(all_forces, o.force_bins, 4.0);
    io::CsvWriter csv(forces_out->stream());
    csv.meta("provenance", provenance);
    csv.meta("contacts", std::to_string(all_forces.size()));
    csv.meta("force_cv", format_number(cv));
    csv.header({"f_over_mean", "probability_density"});
    for (std::size_t b = 0; b < h.centres.size(); ++b) csv.row({format_number(h.centres[b]), format_number(h.density[b])});
  }
  if (summary_out) {
    io::CsvWriter csv(summary_out->stream());
    csv.meta("provenance", provenance);
    csv.header({"packing", "N", "phi", "Z", "contacts", "rattlers", "Z_without_rattlers", "pressure_E",
                "mean_force_Ed2", "force_cv", "max_overlap_d"});
    for (std::size_t k = 0; k < stats.size(); ++k) {
      const auto& s = stats[k];
      csv.row({labels[k], std::to_string(s.spheres), format_number(s.volume_fraction), format_number(s.contact_number),
               std::to_string(s.contacts), std::to_string(s.rattlers), format_number(s.contact_number_without_rattlers),
               format_number(s.pressure), format_number(s.mean_force), format_number(s.force_cv),
               format_number(s.max_overlap)});
    }
  }
  out.commit();
  if (forces_out) forces_out->commit();
  if (summary_out) summary_out->commit();
  if (!o.common.quiet)
    for (std::size_t k = 0; k < stats.size(); ++k) {
      const auto& s = stats[k];
      std::cerr << fmt::format("shellpack: {}: N = {}, phi = {:.5f}, Z = {:.4f} ({} contacts), {} rattlers, "
                               "P = {:.3g} E, contact force cv = {:.3f}\n",
                               labels[k], s.spheres, s.volume_fraction, s.contact_number, s.contacts, s.rattlers,
                               s.pressure, s.force_cv);
    }
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
