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
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"
#include "io/vtk.hpp"
#include "voxel/percolation.hpp"
#include "voxel/percolation_probability.hpp"
#include "voxel/pore_analysis.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <algorithm>
#include <limits>
#include <map>
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

// One run: a packing at one radius scale and one delta.
struct Run {
  std::size_t packing, scale, delta;
};

// What the options ask for, checked: the analysis options, the lists and the runs.
struct Plan {
  voxel::PoreAnalysisOptions ao;
  std::vector<std::string> delta_names, scale_names;
  std::vector<double> deltas, scales;
  std::vector<Run> runs;
  std::vector<std::string> vtk_names;
};

// Records every problem of the options in tool (reported by tool.finish_checks()).
Plan check_percolate(cli::Tool& tool, const Options& o) {
  Plan plan;
  auto& [ao, delta_names, scale_names, deltas, scales, runs, vtk_names] = plan;
  tool.check(!o.inputs.empty(), "", "no packing given (OFF or extended XYZ files)");
  tool.check(std::count(o.inputs.begin(), o.inputs.end(), std::string("-")) <= 1, "",
             "'-' (standard input) given more than once: it can be read only once");
  tool.check(!o.deltas.empty(), "--delta", "required: the lattice constant(s) in D0, e.g. --delta 0.04");
  if (!o.deltas.empty()) deltas = parse_list(tool, "--delta", o.deltas, delta_names);
  scales = parse_list(tool, "--scale", o.scales, scale_names);
  tool.collect("--marking", [&] { ao.shell_marking = voxel::shell_marking_from_name(o.marking); });
  tool.collect("--sphere-marking", [&] { ao.sphere_marking = voxel::sphere_marking_from_name(o.sphere_marking); });
  tool.collect("--connectivity", [&] { ao.connectivity = voxel::connectivity_from_name(o.connectivity); });
  tool.collect("--axis", [&] { ao.flow_axis = voxel::axis_from_name("--axis", o.axis); });
  // Runs in this order: packings, then scales, then deltas (the CSV rows and -o files alike).
  for (std::size_t i = 0; i < o.inputs.size(); ++i)
    for (std::size_t s = 0; s < scales.size(); ++s)
      for (std::size_t k = 0; k < deltas.size(); ++k) runs.push_back({i, s, k});
  if (!o.vtk.empty()) {
    for (const auto& r : runs)
      vtk_names.push_back(cli::expand_pattern(
          cli::expand_pattern(cli::expand_pattern(o.vtk, "name", stem(o.inputs[r.packing])), "scale", scale_names[r.scale]),
          "delta", delta_names[r.delta]));
    tool.check(std::set<std::string>(vtk_names.begin(), vtk_names.end()).size() == vtk_names.size(), "-o",
               "must tell runs apart with {name} (input file name), {scale} and/or {delta} when several "
               "packings, scales or deltas are given, e.g. -o 'cluster_{name}_{scale}_{delta}.vtk'");
  }
  ao.thickness = o.thickness;
  ao.periodic_perpendicular = o.periodic;
  return plan;
}

void run_percolate(const Options& o, const Plan& plan, const std::string& provenance) {
  // plan.runs and plan.vtk_names checked the options per input; the runs below cover every frame.
  const auto& ao = plan.ao;
  const auto &delta_names = plan.delta_names, &scale_names = plan.scale_names;
  const auto &deltas = plan.deltas, &scales = plan.scales;

  // Read every packing first: a bad file stops the run before any output is written. An
  // extended XYZ gives one packing per frame (frame 0, 1, ... as ASE and OVITO count them).
  std::vector<std::vector<voxel::Packing>> per_input(o.inputs.size());
  parallel_for_each_job(static_cast<long>(o.inputs.size()),
                        [&](long i) { per_input[i] = voxel::read_packings(o.inputs[i], {1.0, o.d0}); });
  std::vector<voxel::Packing> packings;
  std::vector<std::size_t> input_of;
  std::vector<int> frame_of;
  bool several_frames = false;
  for (std::size_t i = 0; i < per_input.size(); ++i) {
    several_frames |= per_input[i].size() > 1;
    for (std::size_t f = 0; f < per_input[i].size(); ++f) {
      packings.push_back(std::move(per_input[i][f]));
      input_of.push_back(i);
      frame_of.push_back(static_cast<int>(f));
    }
  }
  if (several_frames && !o.vtk.empty() && o.vtk.find("{frame}") == std::string::npos)
    throw UsageError("-o: an input holds several frames: tell them apart with {frame}, e.g. "
                     "-o 'cluster_{name}_{frame}_{delta}.vtk'");
  // The runs over every frame: packings, then scales, then deltas (the CSV rows and -o files alike).
  std::vector<Run> runs;
  std::vector<std::string> vtk_names;
  for (std::size_t i = 0; i < packings.size(); ++i)
    for (std::size_t s = 0; s < scales.size(); ++s)
      for (std::size_t k = 0; k < deltas.size(); ++k) {
        runs.push_back({i, s, k});
        if (!o.vtk.empty())
          vtk_names.push_back(cli::expand_pattern(
              cli::expand_pattern(cli::expand_pattern(cli::expand_pattern(o.vtk, "name", stem(o.inputs[input_of[i]])),
                                                      "frame", std::to_string(frame_of[i])),
                                  "scale", scale_names[s]),
              "delta", delta_names[k]));
      }
  for (const auto& p : packings) {
    if (p.kind == voxel::Packing::Kind::Shells)
      for (std::size_t s = 0; s < scales.size(); ++s)
        if (scales[s] != 1)
          throw UsageError(fmt::format("{}: --scale {} applies to sphere packings (extended XYZ) only; this is a "
                                       "packing of shells", p.file, scale_names[s]));
    for (std::size_t k = 0; k < deltas.size(); ++k)
      if (deltas[k] * p.d0 > p.box.minCoeff())
        throw UsageError(fmt::format("{}: --delta {} is larger than the box (smallest side {} = {:.4g} D0, D0 = {} from {})",
                                     p.file, delta_names[k], p.box.minCoeff(), p.box.minCoeff() / p.d0,
                                     io::format_number(p.d0), p.d0_source));
  }
  // The CSV's temporary appears with its first row, not before: a run stopped or failed
  // during the first analysis leaves no file at all.
  io::AtomicOutput csv_out(o.csv);
  std::optional<io::CsvWriter> csv;
  const auto start_csv = [&](const std::vector<std::string>& columns) {
    csv.emplace(csv_out.stream());
    csv->meta("provenance", provenance);
    csv->meta("connectivity", o.connectivity);
    csv->meta("labelling", o.periodic ? "periodic perpendicular to each axis" : "not periodic (scipy.ndimage.label)");
    csv->meta("porosity", "geometric, without voxels: porosity_method shell_volumes = 1 - sum of shell volumes / "
                          "V_box; sphere_pair_lenses = 1 - (sum of sphere volumes - pair lenses) / V_box, exact where "
                          "porosity_exact = 1, else an upper bound; porosity_voxels = void voxels / voxels");
    csv->meta("units", "delta, delta_*_d0 and rh_*_d0 in D0; rh_*_delta in voxel sides (actual spacing); VTK origin "
                       "and spacing in the packing's length units");
    csv->header(columns);
  };
  std::vector<std::string> summaries, inexact;
  long inexact_runs = 0;
  {
    cli::ProgressBar bar("percolate", static_cast<double>(runs.size()), o.common.quiet);
    voxel::Packing scaled;
    std::size_t done = 0;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const auto& run = runs[r];
      if (r == 0 || runs[r - 1].packing != run.packing || runs[r - 1].scale != run.scale) {
        scaled = packings[run.packing];
        if (scaled.kind == voxel::Packing::Kind::Spheres) {
          scaled.radii *= scales[run.scale];
          scaled.scale = scales[run.scale];
        }
      }
      const auto& p = scaled;
      std::vector<std::uint8_t> cluster;
      const auto a = voxel::analyse_pores(p, deltas[run.delta], ao, o.vtk.empty() ? nullptr : &cluster);
      if (run.delta == 0 && !a.geometry.exact) {
        ++inexact_runs;
        if (inexact.size() < 3)
          inexact.push_back(fmt::format("{} at scale {}: {} triples of spheres share a point, {} spheres or pairs "
                                        "overlap through a periodic image", p.file, scale_names[run.scale],
                                        a.geometry.triple_overlaps, a.geometry.image_overlaps));
      }
      std::vector<std::pair<std::string, std::string>> fields{
          {"file", p.file},
          {"frame", std::to_string(frame_of[run.packing])},
          {"kind", p.kind == voxel::Packing::Kind::Shells ? "shells" : "spheres"},
          {"particles", std::to_string(p.particles())},
          {"d0", io::format_number(p.d0)},
          {"d0_source", p.d0_source},
          {"scale", io::format_number(p.scale)},
          {"delta", delta_names[run.delta]}};
      for (auto& f : voxel::pore_analysis_fields(a)) fields.push_back(std::move(f));
      if (!csv) {
        std::vector<std::string> names;
        for (const auto& f : fields) names.push_back(f.first);
        start_csv(names);
      }
      std::vector<std::string> row;
      for (const auto& f : fields) row.push_back(f.second);
      csv->row(row);
      if (!o.vtk.empty()) {
        io::VoxelImage<std::uint8_t> img;
        img.dims = a.grid.dims;
        img.spacing = a.grid.spacing;       // in the packing's own length units, so the cluster
        img.origin = 0.5 * a.grid.spacing;  // overlays the packing; points at the voxel centres
        img.name = "cluster";
        img.data = std::move(cluster);
        // What lbflow and a ParaView user need to put the image back in D0 units.
        img.field_data = {{"delta", deltas[run.delta]}, {"d0", p.d0}, {"scale", p.scale}};
        io::write_vtk(vtk_names[r], img,
                      fmt::format("percolating cluster along {} of {} scale={} delta={} D0={} ({}) marking={} "
                                  "(lengths in the packing's units) | {}",
                                  o.axis, p.file, scale_names[run.scale], delta_names[run.delta],
                                  io::format_number(p.d0), p.d0_source, a.marking, provenance));
      }
      std::string summary = fmt::format(
          "percolate: {} scale={} delta={} ({}x{}x{}, D0={} from {}): porosity {:.4f} ({}{}), voxels {:.4f}, "
          "{} clusters, percolates x/y/z {}/{}/{}, R_h {:.4g} D0",
          p.file, scale_names[run.scale], delta_names[run.delta], a.grid.dims[0], a.grid.dims[1], a.grid.dims[2],
          io::format_number(p.d0), p.d0_source, a.geometry.porosity, a.geometry.method,
          a.geometry.exact ? "" : ", upper bound", a.porosity_voxels, a.clusters, int(a.percolates[0]),
          int(a.percolates[1]), int(a.percolates[2]), a.rh_faces_d0);
      if (o.timings)
        summary += fmt::format("; marking {:.3f} s, labelling {:.3f} s", a.seconds_marking, a.seconds_labelling);
      // Below a progress bar the lines wait until it has finished its own line.
      if (bar.enabled()) summaries.push_back(std::move(summary));
      else if (!o.common.quiet || o.timings) std::cerr << summary << '\n';
      bar.update(static_cast<double>(++done));
    }
  }
  for (const auto& line : summaries) std::cerr << line << '\n';
  if (inexact_runs > 0) {
    std::string list;
    for (const auto& s : inexact) list += (list.empty() ? "" : "; ") + s;
    std::cerr << fmt::format("percolate: warning: the pair-lens porosity is an upper bound, not exact, in {} "
                             "packing/scale run(s) (porosity_exact = 0): {}{}\n",
                             inexact_runs, list, inexact_runs > static_cast<long>(inexact.size()) ? "; ..." : "");
  }
  csv_out.commit();
}

// The located message of an InputError without its "file:line: " prefix.
std::string bare_message(const InputError& e) {
  const std::string what = e.what(), name = e.file() == "-" ? "<stdin>" : e.file();
  const std::string prefix = e.line() > 0 ? name + ":" + std::to_string(e.line()) + ": " : name + ": ";
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

void run_sweep(const Options& o, const std::string& provenance) {
  std::vector<voxel::PercolationSample> samples;
  // What must be the same in every row binned together, with where it was first seen.
  struct Seen {
    std::string value, where;
  };
  std::map<std::string, Seen> same;
  auto require_same = [&](const std::string& what, const std::string& value, const std::string& path, long line) {
    const std::string where = fmt::format("{}:{}", path == "-" ? "<stdin>" : path, line);
    auto [it, fresh] = same.try_emplace(what, Seen{value, where});
    if (!fresh && it->second.value != value)
      throw InputError(path, line, fmt::format("{} '{}' differs from '{}' at {}: percolate sweep bins one kind of "
                                               "run at a time (run it per {})", what, value, it->second.value,
                                               it->second.where, what));
  };
  std::map<std::string, std::string> runs_seen;  // file, scale, delta -> where
  std::set<std::string> scales;
  const std::vector<std::string> required{"particles", "delta", o.porosity_column, "percolates"};
  for (const auto& path : o.tables) {
    io::CsvTable t;
    try {
      t = io::read_csv(path);
    } catch (const InputError& e) {
      throw InputError(e.file(), e.line(), "not a percolate CSV (" + bare_message(e) + "); give the CSV rows "
                                           "percolate writes (columns particles, delta, " + o.porosity_column +
                                           ", percolates)");
    }
    for (const auto& name : required)
      if (std::find(t.header.begin(), t.header.end(), name) == t.header.end())
        throw InputError(path, t.header_line, fmt::format("not a percolate CSV: no column '{}' (percolate sweep needs "
                                                          "particles, delta, {}, percolates)", name, o.porosity_column));
    auto optional_column = [&](const std::string& name) {
      const auto it = std::find(t.header.begin(), t.header.end(), name);
      return it == t.header.end() ? -1 : static_cast<int>(it - t.header.begin());
    };
    const int cn = t.column("particles"), cd = t.column("delta"), cp = t.column(o.porosity_column),
              cy = t.column("percolates");
    for (const char* key : {"connectivity", "labelling"})
      if (const auto* v = t.find_meta(key)) require_same(key, *v, path, 1);
    const int cfile = optional_column("file"), cframe = optional_column("frame"), cscale = optional_column("scale");
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const long line = t.row_lines[r];
      for (const char* key : {"kind", "marking", "flow_axis", "porosity_method"})
        if (const int c = optional_column(key); c >= 0) require_same(key, t.rows[r][c], path, line);
      voxel::PercolationSample s;
      s.particles = static_cast<int>(io::parse_integer(t.rows[r][cn], path, line, "a particle count (particles)", 1,
                                                       std::numeric_limits<int>::max()));
      s.delta = t.number(r, cd);
      s.porosity = t.number(r, cp);
      s.percolates = io::parse_integer(t.rows[r][cy], path, line, "0 or 1 (percolates)", 0, 1) == 1;
      if (cscale >= 0) scales.insert(io::format_number(t.number(r, cscale)));
      if (cfile >= 0) {
        const std::string key = t.rows[r][cfile] + "\n" + (cframe >= 0 ? t.rows[r][cframe] : "") + "\n" +
                                (cscale >= 0 ? t.rows[r][cscale] : "") + "\n" +
                                io::format_number(s.delta);
        const std::string where = fmt::format("{}:{}", path == "-" ? "<stdin>" : path, line);
        auto [it, fresh] = runs_seen.try_emplace(key, where);
        if (!fresh)
          throw InputError(path, line, fmt::format("the run of {} at scale {} and delta {} is also at {}: a table "
                                                   "given twice?", t.rows[r][cfile],
                                                   cscale >= 0 ? t.rows[r][cscale] : "?", t.rows[r][cd], it->second));
      }
      samples.push_back(s);
    }
  }
  const auto bins = voxel::percolation_probability(samples, o.bins);
  io::AtomicOutput out(o.csv);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  csv.meta("porosity_column", o.porosity_column);
  csv.meta("groups", "particles,delta (each group's porosity range cut into " + std::to_string(o.bins) + " bins)");
  if (!scales.empty()) {
    std::string list;
    for (const auto& s : scales) list += (list.empty() ? "" : ",") + s;
    csv.meta("scales", list + " (binned together: porosity is the variable)");
  }
  for (const auto& [key, seen] : same) csv.meta(key, seen.value);
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
    app->add_option("-o,--output", o.vtk, "percolating cluster as binary VTK STRUCTURED_POINTS (1 = cluster; origin "
                                          "and spacing in the packing's length units, so it overlays the packing; "
                                          "scale, delta and D0 in the title and as field data delta, d0, scale); "
                                          "with several packings, frames, scales or deltas use {name}, {frame}, "
                                          "{scale} and {delta}");
    app->add_option("--csv", o.csv, "CSV output, one row per packing, scale and delta ('-': stdout); column "
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
    tool.add_int(*sweep, "--bins", o.bins, "porosity bins per (N, delta) over the range of the data", cli::at_least(1));
    sweep->add_option("--porosity", o.porosity_column, "column to bin: porosity (geometric) or porosity_voxels")
        ->capture_default_str();
    sweep->add_option("-o,--output", o.csv, "output CSV ('-': stdout)")->capture_default_str();

    tool.parse(argc, argv);
    Plan plan;
    if (!sweep->parsed()) plan = check_percolate(tool, o);
    tool.finish_checks();
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("percolate", argc, argv);
    if (sweep->parsed()) {
      run_sweep(o, provenance);
      return 0;
    }
    run_percolate(o, plan, provenance);
    return 0;
  });
}
