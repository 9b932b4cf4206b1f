// jam2d: budding cells in 2D (thesis Chapters 2 and 3).
//   jam2d grow --box 15 --seed 1 -o jammed.xyz > growth.csv          from two cells until jammed
//   jam2d grow --box 15 --seed 1 --dphi 0.05 --P0 0.001 -o pack.xyz  beyond jamming, with feedback
//   jam2d moduli pack.xyz > moduli.csv                               P, B, G, Z, f_u of static packings
//   jam2d sweep --box 10 --seeds 1:100 --dphi 0:0.1:0.01 --P0 inf,0.005,0.001 > sweep.csv
//   jam2d chamber --width 6 --height 16 --outlet 1.4 --seed 1 --time 200 -o run.xyz > pressure.csv
//   jam2d avalanches pressure.csv > drops.csv                        drops, rises and outflow events
#include "cells2d/avalanches.hpp"
#include "cells2d/chamber_output.hpp"
#include "cells2d/packing_xyz.hpp"
#include "cells2d/tables.hpp"
#include "cli/progress.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/parallel_for.hpp"
#include "core/registry.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/xyz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <iostream>
#include <memory>

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
  ChamberParameters chamber;
  double duration = 100, sample_every = 0.01, frame_every = 1;
  std::string pressure_column = "pressure_walls", distribution_output;
  double merge = 0.05, from = -1;
};

void add_growth_options(cli::Tool& tool, CLI::App& sub, Options& o) {
  tool.add_double(sub, "--box", o.growth.box, "side L of the periodic square box [sigma]", cli::positive());
  sub.add_option("--contact", o.contact, "contact law between lobes: " + style_names(contact_laws()) + " (--list-models)")
      ->capture_default_str();
  tool.add_double(sub, "--dt0", o.growth.dt0, "growth step dt_0 [1/gamma0]", cli::positive());
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

std::vector<std::pair<std::string, std::string>> packing_info(const Colony& c, std::uint64_t seed, double dphi,
                                                              const std::string& provenance) {
  return {{"tool", provenance},
          {"seed", std::to_string(seed)},
          {"box", io::format_number(c.parameters().box)},
          {"cells", std::to_string(c.cells().size())},
          {"phi", io::format_number(c.area_fraction())},
          {"phi_J", io::format_number(c.phi_jamming())},
          {"dphi", io::format_number(dphi)},
          {"P0", io::format_number(c.parameters().P0)},
          {"time", io::format_number(c.time())},
          {"units", "sigma,k"}};
}

void run_grow(const Options& o, const std::string& provenance) {
  std::unique_ptr<io::AtomicOutput> csv, packing, trajectory;
  if (!o.csv_output.empty()) csv = std::make_unique<io::AtomicOutput>(o.csv_output);
  if (!o.packing_output.empty()) packing = std::make_unique<io::AtomicOutput>(o.packing_output);
  if (!o.trajectory_output.empty()) trajectory = std::make_unique<io::AtomicOutput>(o.trajectory_output);
  std::unique_ptr<io::CsvWriter> table;
  if (csv) {
    table = std::make_unique<io::CsvWriter>(csv->stream());
    table->allow_infinity();  // P0 = inf: no feedback
    table->meta("provenance", provenance);
    table->meta("units", kUnits);
    table->meta("box", io::format_number(o.growth.box));
    table->meta("seed", std::to_string(o.common.seed));
    table->meta("P0", io::format_number(o.growth.P0));
    table->header(growth_columns());
  }
  std::unique_ptr<io::XyzWriter> frames;
  if (trajectory) frames = std::make_unique<io::XyzWriter>(trajectory->stream());
  Colony colony(o.growth, o.common.seed);
  cli::ProgressBar bar("growing", 1.0, o.common.quiet);
  const auto observe = [&](const StepRecord& r) {
    if (table) table->row(growth_row(r));
    if (frames && r.step % o.every == 0)
      frames->write(packing_frame(colony.cells(), o.growth.box, r.packing,
                                  packing_info(colony, o.common.seed, o.dphi, provenance)));
    bar.set_note(fmt::format("{} cells, phi {:.4f}", r.packing->cells, r.packing->area_fraction));
    bar.update(std::min(0.99, r.packing->area_fraction / (0.84 + o.dphi)));
  };
  colony.grow_to_jamming(observe);
  if (o.dphi > 0) colony.grow_beyond(o.dphi, observe);
  bar.finish();
  const auto cells = canonical_cells(colony.cells(), o.growth.box);
  if (packing) {
    Domain d;
    d.lx = d.ly = o.growth.box;
    ContactEngine engine(d, contact_law(o.growth.contact));
    const PackingAnalysis a = analyse_packing(cells, engine);
    io::XyzWriter(packing->stream()).write(packing_frame(cells, o.growth.box, &a,
                                                         packing_info(colony, o.common.seed, o.dphi, provenance)));
  }
  io::commit_in_order({packing.get(), trajectory.get(), csv.get()});
  if (!o.common.quiet)
    std::cerr << fmt::format("jam2d: jammed at phi_J = {:.6f}; {} cells at phi = {:.6f}, t = {:.4f}/gamma0; {} steps "
                             "accepted, {} rejected, {} FIRE iterations\n",
                             colony.phi_jamming(), colony.cells().size(), colony.area_fraction(), colony.time(),
                             colony.counters().accepted, colony.counters().rejected, colony.counters().iterations);
}

void run_moduli(const Options& o, const std::string& provenance) {
  std::vector<CellPacking> packings;
  std::vector<std::pair<std::string, int>> labels;
  for (const auto& path : o.inputs) {
    auto frames = read_packings(path);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      labels.emplace_back(path, static_cast<int>(f));
      packings.push_back(std::move(frames[f]));
    }
  }
  const ContactLawStyle& law = contact_law(o.contact);
  std::vector<Moduli> results(packings.size());
  parallel_for_each_job(static_cast<long>(packings.size()),
                        [&](long k) { results[k] = measure_moduli(packings[k].cells, packings[k].box, law); });
  io::AtomicOutput out(o.output);
  io::CsvWriter table(out.stream());
  table.meta("provenance", provenance);
  table.meta("units", kUnits);
  table.meta("contact", law.name);
  std::vector<std::string> columns = {"file", "frame"};
  for (const auto& c : packing_columns()) columns.push_back(c);
  table.header(columns);
  for (std::size_t k = 0; k < packings.size(); ++k) {
    std::vector<std::string> row = {io::csv_field(labels[k].first), std::to_string(labels[k].second)};
    for (auto& v : packing_row(results[k], packings[k].box)) row.push_back(v);
    table.row(row);
  }
  out.commit();
}

void run_sweep(const Options& o, const std::vector<std::uint64_t>& seeds, const std::string& provenance) {
  io::AtomicOutput out(o.output);
  const long n = static_cast<long>(seeds.size());
  std::vector<std::vector<std::vector<std::string>>> rows(static_cast<std::size_t>(n));
  cli::ProgressBar bar("sweep", static_cast<double>(n), o.common.quiet);
  std::atomic<long> done{0};
  parallel_for_each_job(n, [&](long k) {
    rows[static_cast<std::size_t>(k)] = sweep_seed(seeds[static_cast<std::size_t>(k)], o.growth, o.dphis, o.P0s);
    bar.update(static_cast<double>(++done));
  });
  bar.finish();
  io::CsvWriter table(out.stream());
  table.allow_infinity();  // P0 = inf: no feedback
  table.meta("provenance", provenance);
  table.meta("units", kUnits);
  table.meta("box", io::format_number(o.growth.box));
  table.meta("contact", o.growth.contact);
  table.meta("adaptive_step", o.growth.adaptive_step ? "1" : "0");
  table.meta("step_after_acceptance", o.growth.reset_step ? "reset" : "double");
  table.header(sweep_columns());
  for (const auto& seed_rows : rows)
    for (const auto& r : seed_rows) table.row(r);
  out.commit();
}

void add_chamber_options(cli::Tool& tool, CLI::App& sub, Options& o) {
  ChamberParameters& c = o.chamber;
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
  tool.add_double(sub, "--time", o.duration, "simulated time [1/gamma0]", cli::positive());
  tool.add_double(sub, "--every", o.sample_every, "time between rows of the time series [1/gamma0]", cli::positive());
  tool.add_double(sub, "--frame-every", o.frame_every, "time between trajectory frames [1/gamma0]", cli::positive());
  tool.add_output(sub, "-o,--trajectory", o.trajectory_output, "extended XYZ frames of the chamber ('-': stdout)");
  tool.add_output(sub, "--csv", o.csv_output, "time series, one row per --every ('-': stdout)");
  tool.add_common(sub, o.common, cli::Tool::kSeed | cli::Tool::kQuiet);
}

void run_chamber(const Options& o, const std::string& provenance) {
  std::unique_ptr<io::AtomicOutput> csv, trajectory;
  if (!o.csv_output.empty()) csv = std::make_unique<io::AtomicOutput>(o.csv_output);
  if (!o.trajectory_output.empty()) trajectory = std::make_unique<io::AtomicOutput>(o.trajectory_output);
  const ChamberParameters& p = o.chamber;
  ChamberRun run(p, o.common.seed);
  std::unique_ptr<io::CsvWriter> table;
  if (csv) {
    table = std::make_unique<io::CsvWriter>(csv->stream());
    table->allow_infinity();  // P0 = inf: no feedback
    table->meta("provenance", provenance);
    table->meta("units", kUnits);
    for (const auto& [k, v] : chamber_info(p, o.common.seed)) table->meta(k, v);
    table->header(chamber_columns());
  }
  std::unique_ptr<io::XyzWriter> frames;
  if (trajectory) frames = std::make_unique<io::XyzWriter>(trajectory->stream());
  auto info = chamber_info(p, o.common.seed);
  info.insert(info.begin(), {"tool", provenance});
  cli::ProgressBar bar("chamber", o.duration, o.common.quiet);
  const long samples = std::lround(o.duration / o.sample_every);
  const long frame_stride = std::max(1L, std::lround(o.frame_every / o.sample_every));
  for (long k = 0; k <= samples; ++k) {
    run.advance_to(static_cast<double>(k) * o.sample_every);
    ChamberSample s = run.sample();
    s.time = static_cast<double>(k) * o.sample_every;  // the scheduled time, to within a step
    if (table) table->row(chamber_row(s));
    if (frames && k % frame_stride == 0) frames->write(chamber_frame(run, info));
    bar.set_note(fmt::format("{} cells, P {:.3f} k, {} left", s.chamber_cells, s.pressure_walls, s.left));
    bar.update(run.time());
  }
  bar.finish();
  io::commit_in_order({trajectory.get(), csv.get()});
  if (!o.common.quiet)
    std::cerr << fmt::format("jam2d: t = {}/gamma0 in {} steps (dt {}); {} cells in the chamber, {} divisions, {} left; {} evaluations, {} neighbour-list builds\n",
                             io::format_number(run.time()), run.steps(), io::format_number(p.time_step()),
                             run.cells().size(), run.divisions(), run.left(), run.evaluations(), run.list_builds());
}

void run_avalanches(const Options& o, const std::string& provenance) {
  const io::CsvTable t = io::read_csv(o.inputs.at(0));
  const int time = t.column("time"), pressure = t.column(o.pressure_column), left = t.column("left");
  PressureSeries s;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    s.time.push_back(t.number(r, time));
    s.pressure.push_back(t.number(r, pressure));
    s.left.push_back(static_cast<long>(t.integer(r, left, 0, 1'000'000'000'000LL)));
    if (r > 0 && !(s.time[r] > s.time[r - 1]))
      throw InputError(t.file, t.row_lines[r], "time must increase from row to row");
    if (r > 0 && s.left[r] < s.left[r - 1])
      throw InputError(t.file, t.row_lines[r], "left (cells removed so far) must not decrease");
  }
  const std::vector<Avalanche> events = find_avalanches(s, o.merge, o.from);
  const AvalancheSummary m = summarise(s, events, o.from);
  std::unique_ptr<io::AtomicOutput> distribution;
  if (!o.distribution_output.empty()) distribution = std::make_unique<io::AtomicOutput>(o.distribution_output);
  io::AtomicOutput out(o.output);
  io::CsvWriter table(out.stream());
  const auto num = [](double v) { return io::format_number(v); };
  table.meta("provenance", provenance);
  table.meta("units", kUnits);
  table.meta("input", o.inputs.at(0));
  table.meta("pressure", o.pressure_column);
  if (const auto* seed = t.find_meta("seed")) table.meta("seed", *seed);
  for (const char* key : {"mobility", "P0", "outlet", "attraction"})
    if (const auto* v = t.find_meta(key)) table.meta(key, *v);
  table.meta("from", num(m.from));
  table.meta("to", num(m.to));
  table.meta("mean_pressure", num(m.mean_pressure));
  table.meta("events", std::to_string(m.events));
  table.meta("mean_drop", num(m.mean_drop));
  table.meta("mean_size", num(m.mean_size));
  table.meta("mean_rise_rate", num(m.mean_rise_rate));
  table.meta("mean_drop_rate", num(m.mean_drop_rate));
  table.meta("drop_over_rise_rate", num(m.rate_ratio));
  table.meta("tail_events", std::to_string(m.tail_events));
  table.meta("tail_scale_over_mean_drop", num(m.tail_scale));
  table.meta("tail_ks_distance", num(m.tail_ks));
  table.header({"event", "start", "end", "peak_time", "peak", "base_time", "base", "drop", "rise_rate", "drop_rate",
                "cells"});
  for (std::size_t e = 0; e < events.size(); ++e) {
    const Avalanche& a = events[e];
    table.row({std::to_string(e), num(a.start), num(a.end), num(a.peak_time), num(a.peak), num(a.base_time),
               num(a.base), num(a.drop), num(a.rise_rate), num(a.drop_rate), std::to_string(a.size)});
  }
  if (distribution) {
    // The survival function of the drops in units of their mean (Fig. 2.2e) and the exponential
    // of the fitted tail.
    std::vector<double> drops;
    for (const Avalanche& a : events) drops.push_back(m.mean_drop > 0 ? a.drop / m.mean_drop : 0.0);
    std::sort(drops.begin(), drops.end());
    io::CsvWriter d(distribution->stream());
    d.meta("provenance", provenance);
    d.meta("input", o.inputs.at(0));
    d.meta("mean_drop", num(m.mean_drop));
    d.header({"drop_over_mean", "survival", "exponential_tail"});
    const double n = static_cast<double>(drops.size()), tail = static_cast<double>(m.tail_events) / std::max(1.0, n);
    for (std::size_t i = 0; i < drops.size(); ++i) {
      const double x = drops[i], model = x > 1 && m.tail_scale > 0 ? tail * std::exp(-(x - 1) / m.tail_scale) : 0.0;
      d.row({num(x), num(1 - static_cast<double>(i) / n), num(model)});
    }
  }
  io::commit_in_order({distribution.get(), &out});
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
    avalanches->add_option("series", o.inputs, "time series as `jam2d chamber` writes it ('-': stdin)")->required();
    tool.declare_inputs(*avalanches, o.inputs);
    avalanches->add_option("--pressure", o.pressure_column, "the pressure column: pressure_walls or pressure_virial")
        ->capture_default_str();
    tool.add_double(*avalanches, "--merge", o.merge, "outflow samples closer than this are one event [1/gamma0]",
                    cli::non_negative());
    tool.add_double(*avalanches, "--from", o.from, "analyse from this time [1/gamma0]; -1: from the first outflow");
    tool.add_output(*avalanches, "-o,--output", o.output, "events CSV ('-': stdout)");
    tool.add_output(*avalanches, "--distribution", o.distribution_output,
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
      tool.collect("--P0", [&] { o.chamber.P0 = parse_feedback(o.P0_text); });
      for (const auto& [flag, message] : o.chamber.problems()) tool.check(false, flag, message);
      tool.check(o.sample_every <= o.duration, "--every", "must not exceed --time");
      tool.check(o.duration / o.sample_every <= 1e8, "--every", "more than 1e8 rows: choose a larger --every");
      const int to_stdout = (o.csv_output == "-") + (o.trajectory_output == "-");
      tool.check(to_stdout <= 1, "", "--csv and -o: at most one of them may be '-' (stdout)");
    }
    if (avalanches->parsed()) {
      tool.check(o.pressure_column == "pressure_walls" || o.pressure_column == "pressure_virial", "--pressure",
                 "must be pressure_walls or pressure_virial");
      tool.check(o.from == -1 || o.from >= 0, "--from", "must be a time >= 0, or -1");
    }
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("jam2d", argc, argv);
    if (grow->parsed()) run_grow(o, provenance);
    if (moduli->parsed()) run_moduli(o, provenance);
    if (sweep->parsed()) run_sweep(o, seeds, provenance);
    if (chamber->parsed()) run_chamber(o, provenance);
    if (avalanches->parsed()) run_avalanches(o, provenance);
    return 0;
  });
}
