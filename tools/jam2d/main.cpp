// jam2d: budding cells in 2D (thesis Chapters 2 and 3).
//   jam2d grow --box 15 --seed 1 -o jammed.xyz > growth.csv          from two cells until jammed
//   jam2d grow --box 15 --seed 1 --dphi 0.05 --P0 0.001 -o pack.xyz  beyond jamming, with feedback
//   jam2d moduli pack.xyz > moduli.csv                               P, B, G, Z, f_u of static packings
//   jam2d sweep --box 10 --seeds 1:100 --dphi 0:0.1:0.01 --P0 inf,0.005,0.001 > sweep.csv
//   jam2d chamber --width 6 --height 16 --outlet 1.4 --seed 1 --time 200 -o run.xyz > pressure.csv
//   jam2d avalanches pressure.csv > drops.csv                        drops, rises and outflow events
#include "cells2d/box_jobs.hpp"
#include "cells2d/chamber_job.hpp"
#include "cells2d/tables.hpp"
#include "cli/checkpoint_args.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/registry.hpp"
#include "io/csv.hpp"


#include <fmt/format.h>

#include <iostream>

using namespace cmp;
using namespace cmp::cells2d;

namespace {

struct Options {
  cli::CommonOptions common;
  cli::SeedOptions seeding;
  GrowthParameters growth;
  std::string P0_text = "inf", dphi_text = "0", contact = "harmonic";
  double dphi = 0;
  std::string packing_output, csv_output = "-", trajectory_output;
  long every = 0;
  bool fixed_step = false, double_step = false, list_models = false;
  std::vector<std::string> inputs;
  std::string output = "-";
  std::vector<double> dphis, P0s;
  ChamberJob chamber;
  AvalancheJob avalanches;
};

constexpr double kMaxGrowthStep = 0.1;   // --dt0 [1/gamma0]
constexpr double kMaxChamberSteps = 1e10;  // time steps a chamber run may take (days of CPU)

void add_growth_options(cli::Tool& tool, CLI::App& sub, Options& o) {
  tool.add_double(sub, "--box", o.growth.box, "side L of the periodic square box [sigma]", cli::positive());
  sub.add_option("--contact", o.contact, "contact law between lobes: " + style_names(contact_laws()) + " (--list-models)")
      ->capture_default_str();
  // A step grows each cell by dt_0 gamma_0 of its size: beyond 0.1 a step is a good part of a
  // generation, and far above it (--dt0 1e308) a run went on without end.
  tool.add_double(sub, "--dt0", o.growth.dt0, "growth step dt_0 [1/gamma0]",
                  cli::left_open(0, kMaxGrowthStep).because("a step grows each cell by dt_0 gamma_0 of its size"));
  sub.add_flag("--fixed-step", o.fixed_step, "no adaptive step beyond jamming (thesis Fig. S3.5)");
  sub.add_flag("--double-step", o.double_step,
               "after an accepted step double dt (up to dt_0) instead of the thesis's reset to dt_0: the same "
               "jamming criterion, several times faster near jamming");
}

void check_growth(cli::Tool& tool, Options& o) {
  o.growth.contact = o.contact;
  o.growth.adaptive_step = !o.fixed_step;
  o.growth.reset_step = !o.double_step;
  tool.check(o.growth.box >= 2.61 || o.growth.box <= 0, "--box", "must be at least 2.61 sigma (twice the lobe cutoff and skin)");
  // A colony fills its box: of the order of L^2 cells at jamming. --box 1e300 grew for ever.
  tool.check(o.growth.box <= 1000, "--box", "must be at most 1000 sigma (a colony jams with of the order of L^2 cells)");
  tool.collect("--contact", [&] { contact_law(o.contact); });
}

void add_chamber_options(cli::Tool& tool, CLI::App& sub, Options& o) {
  ChamberParameters& c = o.chamber.parameters;
  tool.add_double(sub, "--width", c.geometry.width, "chamber width L_x [sigma]");
  tool.add_double(sub, "--height", c.geometry.height, "chamber height L_y [sigma]");
  tool.add_double(sub, "--outlet", c.geometry.outlet, "outlet width a, centred in the bottom wall [sigma]");
  tool.add_double(sub, "--channel", c.geometry.channel, "length of the outlet channel; cells past it are removed [sigma]");
  sub.add_option("--contact", c.contact, "contact law between lobes: " + style_names(contact_laws()) + " (--list-models)")
      ->capture_default_str();
  tool.add_double(sub, "--attraction", c.attraction, "width Delta of the sticky law's attractive range [sigma]");
  tool.add_double(sub, "--mobility", c.mobility, "mobility mu k / gamma0 (thesis: 8e4 without feedback, 2e3 with)");
  tool.add_double(sub, "--dt", c.dt, "time step [1/gamma0]; 0: the integrator's stability limit / (20 mobility)");
  sub.add_option("--integrator", c.integrator, "integrator: " + style_names(integrator_styles()))->capture_default_str();
  tool.add_double(sub, "--rate-spread", c.rate_spread, "gamma0_i uniform in [1 - s, 1 + s] gamma0");
  sub.add_option("--P0", o.P0_text, "feedback pressure P0 [k] ('inf': none)")->capture_default_str();
  sub.add_option("--feedback-pressure", c.feedback_pressure, "the pressure that slows a cell: cell or bud")
      ->capture_default_str();
  tool.add_double(sub, "--feedback-interval", c.feedback_interval, "time between growth-rate updates [1/gamma0]");
  ChamberJob& j = o.chamber;
  tool.add_double(sub, "--time", j.duration, "simulated time [1/gamma0]", cli::positive());
  tool.add_double(sub, "--every", j.sample_every, "time between rows of the time series [1/gamma0]", cli::positive());
  tool.add_double(sub, "--frame-every", j.frame_every, "time between trajectory frames [1/gamma0]", cli::positive());
  tool.add_output(sub, "-o,--trajectory", j.trajectory, "extended XYZ frames of the chamber ('-': stdout)");
  tool.add_output(sub, "--csv", j.csv, "time series, one row per --every ('-': stdout; '' for none)");
  tool.add_output(sub, "--checkpoint", j.checkpoint, "save the run here every --checkpoint-every seconds and at the end");
  tool.add_double(sub, "--checkpoint-every", j.checkpoint_every, "seconds between checkpoints", cli::non_negative());
  sub.add_option("--resume", j.resume, "continue the run saved in this checkpoint (repeat the run's options)");
  tool.add_double(sub, "--stop-after", j.stop_after, "stop at this time with a checkpoint and no outputs (for tests)");
  tool.add_common(sub, o.common, cli::Tool::kSeed | cli::Tool::kQuiet);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("jam2d", [&] {
    Options o;
    cli::Tool tool("jam2d", "Budding cells in 2D: growth-driven jamming in a periodic box (thesis Ch. 3).");
    auto* app = &tool.app();
    app->require_subcommand(0, 1);
    tool.add_common(*app, o.common, cli::Tool::kQuiet);
    app->add_flag("--list-models", o.list_models, "list the contact laws between lobes (CSV) and exit");

    auto* grow = app->add_subcommand("grow", "grow a colony from two cells until jammed (and beyond); CSV row per accepted step");
    add_growth_options(tool, *grow, o);
    tool.add_common(*grow, o.common, cli::Tool::kSeed | cli::Tool::kQuiet);
    tool.add_double(*grow, "--dphi", o.dphi, "grow beyond jamming to phi_J + dphi", cli::non_negative());
    grow->add_option("--P0", o.P0_text, "feedback pressure P0 [k] beyond jamming ('inf': none)");
    tool.add_output(*grow, "-o,--packing", o.packing_output, "write the final packing as extended XYZ ('-': stdout)");
    tool.add_output(*grow, "--csv", o.csv_output, "growth table, one row per accepted step ('-': stdout; '' for none)");
    tool.add_output(*grow, "--trajectory", o.trajectory_output, "write every --every-th accepted step as XYZ frames");
    tool.add_long(*grow, "--every", o.every, "accepted steps between --trajectory frames", cli::at_least(1));

    auto* moduli = app->add_subcommand("moduli", "P, B, G, Z, Z_iso, f_u and rattlers of static packings; CSV row per frame");
    moduli->add_option("packings", o.inputs, "extended XYZ packings as jam2d writes them ('-': stdin)")->required();
    tool.declare_inputs(*moduli, o.inputs);
    tool.add_output(*moduli, "-o,--output", o.output, "CSV ('-': stdout)");
    moduli->add_option("--contact", o.contact, "contact law the packing was made with");
    tool.add_common(*moduli, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto* sweep = app->add_subcommand("sweep", "many inoculations on all cores; CSV row per seed, P0 and dphi");
    add_growth_options(tool, *sweep, o);
    tool.add_seed_options(*sweep, o.seeding, "colony");
    sweep->add_option("--dphi", o.dphi_text, "dphi values: FIRST:LAST:STEP or a comma list (0: at jamming)");
    sweep->add_option("--P0", o.P0_text, "comma list of feedback pressures [k], 'inf' for none");
    tool.add_output(*sweep, "-o,--output", o.output, "CSV ('-': stdout)");
    tool.add_common(*sweep, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto* chamber = app->add_subcommand("chamber", "cells proliferating in a chamber with an outlet (thesis Ch. 2); "
                                                   "CSV row per --every");
    add_chamber_options(tool, *chamber, o);

    auto* avalanches = app->add_subcommand("avalanches", "outflow events of a chamber's time series: pressure drops, "
                                                         "rises and avalanche sizes; CSV row per event");
    AvalancheJob& av = o.avalanches;
    avalanches->add_option("series", av.input, "time series as `jam2d chamber` writes it ('-': stdin)")->required();
    tool.declare_input(*avalanches, av.input);
    avalanches->add_option("--pressure", av.pressure_column, "the pressure column: pressure_walls or pressure_virial")
        ->capture_default_str();
    tool.add_double(*avalanches, "--merge", av.merge, "outflow samples closer than this are one event [1/gamma0]",
                    cli::non_negative());
    tool.add_double(*avalanches, "--from", av.from, "analyse from this time [1/gamma0]; -1: from the first outflow");
    tool.add_output(*avalanches, "-o,--output", av.output, "events CSV ('-': stdout)");
    tool.add_output(*avalanches, "--distribution", av.distribution,
                    "survival function of the drops over their mean, with the exponential tail fit (CSV)");
    tool.add_common(*avalanches, o.common, cli::Tool::kQuiet);

    tool.parse(argc, argv);
    if (o.list_models) {
      write_style_header(std::cout);
      write_styles(std::cout, "contact", contact_laws());
      write_styles(std::cout, "integrator", integrator_styles());
      return 0;
    }
    tool.check(app->get_subcommands().size() == 1, "", "a subcommand is required: grow, moduli, sweep, chamber or avalanches (or --list-models)");
    std::vector<std::uint64_t> seeds;
    if (grow->parsed()) {
      check_growth(tool, o);
      tool.collect("--P0", [&] { o.growth.P0 = parse_feedback(o.P0_text); });
      tool.check(!o.trajectory_output.empty() || o.every == 0, "--every", "needs --trajectory");
      if (!o.trajectory_output.empty() && o.every == 0) o.every = 1;
      const int to_stdout = (o.csv_output == "-") + (o.packing_output == "-") + (o.trajectory_output == "-");
      tool.check(to_stdout <= 1, "", "--csv, -o and --trajectory: at most one of them may be '-' (stdout)");
    }
    if (moduli->parsed()) tool.collect("--contact", [&] { contact_law(o.contact); });
    if (sweep->parsed()) {
      check_growth(tool, o);
      tool.collect("--P0", [&] { o.P0s = parse_feedback_list(o.P0_text); });
      tool.collect("--dphi", [&] { o.dphis = parse_dphi_list(o.dphi_text); });
      seeds = tool.seed_list(o.seeding);
      tool.check(!o.seeding.resume, "--resume", "sweep writes one table; run the missing seeds and join the tables");
    }
    if (chamber->parsed()) {
      ChamberJob& j = o.chamber;
      tool.collect("--P0", [&] { j.parameters.P0 = parse_feedback(o.P0_text); });
      const auto problems = j.parameters.problems();
      for (const auto& [flag, message] : problems) tool.check(false, flag, message);
      // The number of steps the options imply: --mobility 1e12 ran without end.
      if (problems.empty()) {
        const double dt = j.parameters.time_step(), steps = j.duration / dt;
        tool.check(steps <= kMaxChamberSteps, j.parameters.dt > 0 ? "--dt" : "--mobility",
                   fmt::format("{} with --time {} implies {:.3g} time steps of {:.3g}{}: more than {:g}; lower "
                               "--time{}",
                               fmt::format("{:g}", j.parameters.dt > 0 ? j.parameters.dt : j.parameters.mobility),
                               io::format_number(j.duration), steps, dt,
                               j.parameters.dt > 0 ? "" : " (the integrator's stability limit / (20 mobility))",
                               kMaxChamberSteps, j.parameters.dt > 0 ? " or raise --dt" : " or --mobility"));
      }
      tool.check(j.sample_every <= j.duration, "--every", "must not exceed --time");
      tool.check(j.duration / j.sample_every <= 1e8, "--every", "more than 1e8 rows: choose a larger --every");
      const int to_stdout = (j.csv == "-") + (j.trajectory == "-");
      tool.check(to_stdout <= 1, "", "--csv and -o: at most one of them may be '-' (stdout)");
      tool.check(j.resume.empty() || j.resume != "-", "--resume", "needs a file, not stdin");
      tool.check(j.stop_after < 0 || !j.checkpoint.empty(), "--stop-after", "needs --checkpoint");
      j.seed = o.common.seed;
      j.quiet = o.common.quiet;
    }
    if (avalanches->parsed()) {
      const AvalancheJob& av = o.avalanches;
      tool.check(av.pressure_column == "pressure_walls" || av.pressure_column == "pressure_virial", "--pressure",
                 "must be pressure_walls or pressure_virial");
      tool.check(av.from == -1 || av.from >= 0, "--from", "must be a time >= 0, or -1");
    }
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("jam2d", argc, argv);
    if (grow->parsed())
      run_grow_job({o.growth, o.common.seed, o.dphi, o.packing_output, o.csv_output, o.trajectory_output, o.every,
                    o.common.quiet, provenance});
    if (moduli->parsed()) run_moduli_job({o.inputs, o.output, o.contact, provenance});
    if (sweep->parsed()) run_sweep_job({o.growth, seeds, o.dphis, o.P0s, o.output, o.common.quiet, provenance});
    if (chamber->parsed()) {
      // The run without the options that steer only this process: a stopped and resumed run
      // then records the same provenance, so writes the same bytes, as one never stopped.
      static constexpr cli::ProcessOnlyOption kProcessOnly[] = {
          {"--resume", true}, {"--stop-after", true}, {"--checkpoint-every", true}, {"-q", false}, {"--quiet", false}};
      const std::vector<std::string> args(argv, argv + argc);
      o.chamber.provenance = cli::provenance("jam2d", cli::checkpoint_arguments(args, kProcessOnly));
      run_chamber_job(o.chamber);
    }
    if (avalanches->parsed()) {
      o.avalanches.provenance = provenance;
      run_avalanche_job(o.avalanches);
    }
    return 0;
  });
}
