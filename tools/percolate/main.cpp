// percolate: from a packing to its pore space, the percolating cluster, porosity and
// hydraulic radius (thesis 5.2.2, 5.3.1-5.3.2).
//   percolate pack_0.85.off --delta 0.04 -o cluster.vtk > percolate.csv     shells (packing OFF)
//   percolate jammed.xyz --delta 0.04 --scale 1.05 -o cluster.vtk           spheres (extended XYZ)
//   percolate packs/*.off --delta 0.03,0.04,0.05 --threads 2 > perc.csv     many packings, many delta
//   percolate sweep perc.csv --bins 10 > probability.csv                   P(percolates) vs porosity
#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"
#include "io/vtk.hpp"
#include "voxel/percolate_run.hpp"
#include "voxel/percolation.hpp"
#include "voxel/percolation_probability.hpp"
#include "voxel/percolation_table.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::vector<std::string> inputs;
  std::string deltas, scales = "1", vtk, csv = "-";
  double d0 = 0, thickness = 0;
  std::string marking = "triangles", sphere_marking = "overlap", connectivity = "6", axis = "x";
  bool periodic = false, timings = false;
  // sweep
  std::vector<std::string> tables;
  int bins = 10;
  std::string porosity_column = "porosity";
};

// A comma-separated list of positive numbers, with the tokens as typed (for {delta}, {scale});
// a bad token is recorded as a problem of flag, and the list is then empty (no runs).
std::vector<double> parse_list(cli::Tool& tool, const std::string& flag, const std::string& text,
                               std::vector<std::string>& names) {
  std::vector<double> out;
  std::size_t at = 0;
  bool ok = true;
  while (at <= text.size()) {
    const auto comma = std::min(text.find(',', at), text.size());
    const std::string token = text.substr(at, comma - at);
    double v = 0;
    std::string problem;
    if (!io::try_parse_double(token, v)) problem = "'" + token + "' is not a finite number";
    else if (!(v > 0)) problem = "must be positive, got '" + token + "'";
    if (!problem.empty()) {
      tool.check(false, flag, problem);
      ok = false;
    }
    out.push_back(v);
    names.push_back(token);
    at = comma + 1;
  }
  if (!ok) out.clear(), names.clear();
  return out;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// Records every problem of the options in tool (reported by tool.finish_checks()); the plan
// still lacks its provenance.
voxel::PercolatePlan check_percolate(cli::Tool& tool, const Options& o) {
  voxel::PercolatePlan plan;
  auto& ao = plan.analysis;
  tool.check(!o.inputs.empty(), "", "no packing given (OFF or extended XYZ files)");
  tool.check(std::count(o.inputs.begin(), o.inputs.end(), std::string("-")) <= 1, "",
             "'-' (standard input) given more than once: it can be read only once");
  tool.check(!o.deltas.empty(), "--delta", "required: the lattice constant(s) in D0, e.g. --delta 0.04");
  if (!o.deltas.empty()) plan.deltas = parse_list(tool, "--delta", o.deltas, plan.delta_names);
  plan.scales = parse_list(tool, "--scale", o.scales, plan.scale_names);
  tool.collect("--marking", [&] { ao.shell_marking = voxel::shell_marking_from_name(o.marking); });
  tool.collect("--sphere-marking", [&] { ao.sphere_marking = voxel::sphere_marking_from_name(o.sphere_marking); });
  tool.collect("--connectivity", [&] { ao.connectivity = voxel::connectivity_from_name(o.connectivity); });
  tool.collect("--axis", [&] { ao.flow_axis = voxel::axis_from_name("--axis", o.axis); });
  // -o's folders may hold {name}, {scale} and {delta}: each is checked ({frame} only when written).
  std::vector<std::string> names;
  for (const auto& in : o.inputs) names.push_back(stem(in));
  tool.set_placeholder_values("name", names);
  tool.set_placeholder_values("scale", plan.scale_names);
  tool.set_placeholder_values("delta", plan.delta_names);
  if (!o.vtk.empty()) {  // checked per input; run_percolate names the files of every frame
    std::vector<std::string> vtk_names;
    for (const auto& r : voxel::percolate_runs(o.inputs.size(), plan.scales.size(), plan.deltas.size()))
      vtk_names.push_back(cli::expand_pattern(
          cli::expand_pattern(cli::expand_pattern(o.vtk, "name", stem(o.inputs[r.packing])), "scale",
                              plan.scale_names[r.scale]),
          "delta", plan.delta_names[r.delta]));
    tool.check(std::set<std::string>(vtk_names.begin(), vtk_names.end()).size() == vtk_names.size(), "-o",
               "must tell runs apart with {name} (input file name), {scale} and/or {delta} when several "
               "packings, scales or deltas are given, e.g. -o 'cluster_{name}_{scale}_{delta}.vtk'");
  }
  ao.thickness = o.thickness;
  ao.periodic_perpendicular = o.periodic;
  plan.axis_name = o.axis;
  plan.connectivity_name = o.connectivity;
  plan.images = !o.vtk.empty();
  plan.timings = o.timings;
  return plan;
}

void run_percolate(const Options& o, const voxel::PercolatePlan& plan) {
  // Every packing is read first: a bad file stops the run before any output is written.
  const auto frames = voxel::read_packing_frames(o.inputs, {1.0, o.d0});
  if (frames.several_frames && !o.vtk.empty() && o.vtk.find("{frame}") == std::string::npos)
    throw UsageError("-o: an input holds several frames: tell them apart with {frame}, e.g. "
                     "-o 'cluster_{name}_{frame}_{delta}.vtk'");
  const auto runs = voxel::percolate_runs(frames.packings.size(), plan.scales.size(), plan.deltas.size());
  std::vector<std::string> vtk_names;
  if (!o.vtk.empty())
    for (const auto& r : runs)
      vtk_names.push_back(cli::expand_pattern(
          cli::expand_pattern(cli::expand_pattern(cli::expand_pattern(o.vtk, "name", stem(o.inputs[frames.input_of[r.packing]])),
                                                  "frame", std::to_string(frames.frame_of[r.packing])),
                              "scale", plan.scale_names[r.scale]),
          "delta", plan.delta_names[r.delta]));
  voxel::check_percolate_plan(frames.packings, plan);
  // The CSV's temporary appears with its first row, not before: a run stopped or failed
  // during the first analysis leaves no file at all.
  io::AtomicOutput csv_out(o.csv);
  std::optional<io::CsvWriter> csv;
  io::SecondaryOutputs images;  // a cluster image that cannot be written does not lose the table
  std::vector<std::string> summaries;
  std::string warning;
  {
    cli::ProgressBar bar("percolate", static_cast<double>(runs.size()), o.common.quiet);
    warning = voxel::run_percolate(frames, plan, runs, [&](std::size_t r, voxel::PercolateRunResult& result) {
      if (!csv) voxel::write_percolate_csv_header(csv.emplace(csv_out.stream()), plan, result.columns);
      csv->row(result.row);
      if (!o.vtk.empty()) images.attempt([&] { io::write_vtk(vtk_names[r], result.image, result.title); });
      // Below a progress bar the lines wait until it has finished its own line.
      if (bar.enabled()) summaries.push_back("percolate: " + result.summary);
      else if (!o.common.quiet || o.timings) std::cerr << "percolate: " << result.summary << '\n';
      bar.update(static_cast<double>(r + 1));
    });
  }
  for (const auto& line : summaries) std::cerr << line << '\n';
  if (!warning.empty()) std::cerr << "percolate: " << warning << '\n';
  images.commit_then_throw({&csv_out});
}

void run_sweep(const Options& o, const std::string& provenance) {
  const auto tables = voxel::read_percolation_tables(o.tables, o.porosity_column);
  const auto bins = voxel::percolation_probability(tables.samples, o.bins);
  io::AtomicOutput out(o.csv);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  csv.meta("porosity_column", o.porosity_column);
  csv.meta("groups", "particles,delta (each group's porosity range cut into " + std::to_string(o.bins) + " bins)");
  if (!tables.scales.empty()) {
    std::string list;
    for (const auto& s : tables.scales) list += (list.empty() ? "" : ",") + s;
    csv.meta("scales", list + " (binned together: porosity is the variable)");
  }
  for (const auto& [key, value] : tables.same) csv.meta(key, value);
  csv.header({"particles", "delta", "porosity", "porosity_low", "porosity_high", "packings", "percolating",
              "probability", "probability_error"});
  for (const auto& b : bins)
    csv.row({std::to_string(b.particles), io::format_number(b.delta), io::format_number(b.porosity_mean),
             io::format_number(b.porosity_low), io::format_number(b.porosity_high), std::to_string(b.packings),
             std::to_string(b.percolating), io::format_number(b.probability), io::format_number(b.probability_error)});
  out.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("percolate", [&] {
    Options o;
    cli::Tool tool("percolate",
                   "Pore space of a packing on a lattice of side delta: porosity, connected clusters, "
                             "percolation per axis, hydraulic radius, the percolating cluster as VTK (thesis 5.2.2). One CSV row "
                             "per packing, scale and delta on stdout, a summary line per run on stderr (-q: none).");
    auto* app = &tool.app();
    app->add_option("packings", o.inputs, "packings: OFF of shells ('# box' needed) or extended XYZ of spheres (a "
                                          "radius column; every frame is a packing), told from the content; '-' "
                                          "reads either from stdin");
    tool.declare_inputs(*app, o.inputs);
    app->add_option("-d,--delta", o.deltas, "lattice constant(s) delta [D0], comma separated, e.g. 0.03,0.04,0.05");
    tool.add_double(*app, "--d0", o.d0, "D0, the unit of delta [length units of the file]; 0 (default): a 'D0=' "
                                         "comment of the file, else the volume-equivalent diameter of the mean shell "
                                         "(OFF) or the mean unscaled sphere diameter (XYZ); the CSV says which "
                                         "(d0_source)", cli::non_negative());
    app->add_option("--scale", o.scales, "spheres: multiply every radius by this factor (inflation), comma separated "
                                         "for several, e.g. 1.0,1.1,1.2; runs are packings x scales x deltas")
        ->capture_default_str();
    app->add_option("--marking", o.marking, "shells: 'triangles' (conservative triangle-voxel overlap) or 'vertices' "
                                            "(thesis; leaks when delta < edge length)")->capture_default_str();
    tool.add_double(*app, "--thickness", o.thickness, "shells: also mark voxels within this max-norm distance of the "
                                                      "surface [D0]", cli::non_negative());
    app->add_option("--sphere-marking", o.sphere_marking, "spheres: 'overlap' (any part of the voxel inside) or "
                                                          "'centre' (the voxel centre inside)")->capture_default_str();
    app->add_option("--connectivity", o.connectivity, "neighbours of a void voxel: 6 (faces, scipy's default), 18, 26")
        ->capture_default_str();
    app->add_flag("--periodic", o.periodic, "label with periodic faces perpendicular to the axis tested (as LB's "
                                            "boundaries); default: not periodic, as scipy.ndimage.label in the thesis");
    app->add_option("--axis", o.axis, "flow axis: the cluster written and measured (R_h) spans it")->capture_default_str();
    tool.add_output(*app, "-o,--output", o.vtk, "percolating cluster as binary VTK STRUCTURED_POINTS (1 = cluster; origin "
                                          "and spacing in the packing's length units, so it overlays the packing; "
                                          "scale, delta and D0 in the title and as field data delta, d0, scale); "
                                          "with several packings, frames, scales or deltas use {name}, {frame}, "
                                          "{scale} and {delta}");
    tool.add_output(*app, "--csv", o.csv, "CSV output, one row per packing, scale and delta ('-': stdout); column "
                                    "porosity is the geometric porosity (porosity_method says how)")
        ->capture_default_str();
    app->add_flag("--timings", o.timings, "print the wall-clock time of marking and labelling per run on stderr "
                                          "(never in the CSV, so a run gives the same bytes every time)");
    tool.add_common(*app, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);

    auto* sweep = app->add_subcommand("sweep", "percolation probability vs porosity per N and delta, in porosity bins, "
                                               "from percolate's CSV rows (input of kcfit's sigmoid fit)");
    sweep->add_option("tables", o.tables, "CSV files written by percolate ('-': stdin); rows are grouped by "
                                          "particles and delta and binned over porosity, all scales together")
        ->required();
    tool.declare_inputs(*sweep, o.tables);
    tool.add_int(*sweep, "--bins", o.bins, "porosity bins per (N, delta) over the range of the data", cli::at_least(1));
    sweep->add_option("--porosity", o.porosity_column, "column to bin: porosity (geometric) or porosity_voxels")
        ->capture_default_str();
    tool.add_output(*sweep, "-o,--output", o.csv, "output CSV ('-': stdout)")->capture_default_str();

    tool.parse(argc, argv);
    voxel::PercolatePlan plan;
    if (!sweep->parsed()) plan = check_percolate(tool, o);
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("percolate", argc, argv);
    if (sweep->parsed()) {
      run_sweep(o, provenance);
      return 0;
    }
    plan.provenance = provenance;
    run_percolate(o, plan);
    return 0;
  });
}
