#include "jam_command.hpp"

#include <fmt/format.h>

namespace cmp::shellpack {

CLI::App* JamCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  auto& p = batch_.jamming;
  auto& f = p.fire;
  auto* jam = parent.add_subcommand("jam", "jammed packing of N Hertzian spheres in a periodic cube (5.5.1); CSV row per packing");
  tool.add_int(*jam, "-N,--spheres", batch_.spheres, fmt::format("number of spheres N (>= {})", spheres::kMinJammingSpheres))
      ->required();
  tool.add_seed_options(*jam, seeding_, "packing");
  tool.add_common(*jam, common, cli::Tool::kThreads);
  tool.add_output(*jam, "-o,--packing", batch_.packing_output, "write the packing to this extended XYZ file (OVITO, ASE; '-': stdout); with --seeds, {seed} makes one file per seed, else every packing is one frame of this file, in seed order");
  tool.add_output(*jam, "--csv", batch_.csv_output,
                  "CSV of packing figures ('-': stdout; {seed}: one per seed) [default: stdout, none with -o -]");
  jam->add_flag("--timings", batch_.timings, "add the wall time of each packing (`seconds`) to the CSV");
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
  jam->add_flag("--keep-rattlers", keep_rattlers_, "accept packings with rattlers (the thesis rejects them)");
  jam->add_flag("--allow-hyperstatic", allow_hyperstatic_,
                "accept rattler-free packings with more than 3N - 2 contacts (crystallites; the thesis's literal rule)");
  tool.add_common(*jam, common, cli::Tool::kQuiet);
  return jam;
}

void JamCommand::check(cli::Tool& tool) {
  auto& p = batch_.jamming;
  p.reject_rattlers = !keep_rattlers_;
  p.require_isostatic = !allow_hyperstatic_;
  tool.check(batch_.spheres >= spheres::kMinJammingSpheres, "--spheres",
             fmt::format("N = {} is too small: a periodic rattler-free jammed packing needs N >= {} "
                         "(with fewer spheres each would touch two images of another)",
                         batch_.spheres, spheres::kMinJammingSpheres));
  tool.check(batch_.spheres <= spheres::kMaxJammingSpheres, "--spheres",
             fmt::format("N = {} is more than the {} spheres a packing is made of here", batch_.spheres,
                         spheres::kMaxJammingSpheres));
  tool.check(p.fire.dt_max >= p.fire.dt, "--fire-dt-max", "must be at least --fire-dt");
  batch_.seeds = tool.seed_list(seeding_);
  batch_.resume = seeding_.resume;
  const std::string csv = packrun::jam_csv_path(batch_);
  tool.check(!(batch_.packing_output == "-" && csv == "-"), "--csv",
             "the packing already goes to stdout (-o -): write the CSV to a file");
  if (batch_.resume) {
    tool.check(batch_.packing_output.find("{seed}") != std::string::npos, "--resume",
               "needs -o with {seed} (one packing file per seed, e.g. -o 'jammed_{seed}.xyz')");
    tool.check(csv.empty() || csv.find("{seed}") != std::string::npos, "--resume",
               "needs --csv with {seed} (one table per seed, e.g. --csv 'jam_{seed}.csv'): a combined table "
               "would miss the skipped seeds");
  }
  if (tool.problem_count() == 0) tool.collect([&] { p.validate(); });
}

void JamCommand::run(bool quiet, const std::string& provenance) {
  batch_.quiet = quiet;
  packrun::run_jam_batch(batch_, provenance);
}

}  // namespace cmp::shellpack
