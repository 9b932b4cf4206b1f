// percolate: from a packing to its pore space, the percolating cluster, porosity and
// hydraulic radius (thesis 5.2.2, 5.3.1-5.3.2; digest section 4).
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
#include <set>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::vector<std::string> inputs;
  std::string deltas, vtk, csv = "-";
  double d0 = 0, scale = 1, thickness = 0;
  std::string marking = "triangles", sphere_marking = "overlap", connectivity = "6", axis = "x";
  bool periodic = false;
  // sweep
  std::vector<std::string> tables;
  int bins = 10;
  std::string porosity_column = "porosity_geometry_overlap";
};

std::vector<double> parse_deltas(const std::string& text, std::vector<std::string>& names) {
  std::vector<double> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const auto comma = std::min(text.find(',', at), text.size());
    const std::string token = text.substr(at, comma - at);
    double v = 0;
    if (!io::try_parse_double(token, v)) throw UsageError("--delta: '" + token + "' is not a number");
    if (!(v > 0) || !std::isfinite(v)) throw UsageError("--delta must be positive, got " + token);
    out.push_back(v);
    names.push_back(token);
    at = comma + 1;
  }
  return out;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

void run_percolate(const Options& o, const std::string& provenance) {
  voxel::PoreAnalysisOptions ao;
  cli::OptionChecks checks;
  std::vector<std::string> delta_names;
  std::vector<double> deltas;
  auto collect = [&](auto&& f) {
    try {
      f();
    } catch (const UsageError& e) {
      checks.require(false, e.what());
    }
  };
  checks.require(!o.inputs.empty(), "no packing given (OFF or extended XYZ files)");
  collect([&] { deltas = parse_deltas(o.deltas, delta_names); });
  collect([&] { ao.shell_marking = voxel::shell_marking_from_name(o.marking); });
  collect([&] { ao.sphere_marking = voxel::sphere_marking_from_name(o.sphere_marking); });
  collect([&] { ao.connectivity = voxel::connectivity_from_name(o.connectivity); });
  collect([&] { ao.flow_axis = voxel::axis_from_name("--axis", o.axis); });
  checks.require(o.scale > 0 && std::isfinite(o.scale), fmt::format("--scale must be positive, got {}", o.scale));
  checks.require(o.thickness >= 0 && std::isfinite(o.thickness), fmt::format("--thickness must be >= 0, got {}", o.thickness));
  checks.require(o.d0 >= 0 && std::isfinite(o.d0), fmt::format("--d0 must be positive, got {}", o.d0));
  const std::size_t runs = o.inputs.size() * std::max<std::size_t>(deltas.size(), 1);
  std::vector<std::string> vtk_names;
  if (!o.vtk.empty()) {
    for (const auto& in : o.inputs)
      for (const auto& d : delta_names)
        vtk_names.push_back(cli::expand_pattern(cli::expand_pattern(o.vtk, "name", stem(in)), "delta", d));
    checks.require(std::set<std::string>(vtk_names.begin(), vtk_names.end()).size() == vtk_names.size(),
                   "-o must tell runs apart with {name} (input file name) and/or {delta} when several packings or "
                   "deltas are given, e.g. -o 'cluster_{name}_{delta}.vtk'");
  }
  checks.throw_if_any();
  ao.thickness = o.thickness;
  ao.periodic_perpendicular = o.periodic;

  // Read every packing first: a bad file stops the run before any output is written.
  std::vector<voxel::Packing> packings(o.inputs.size());
  parallel_for_each_job(static_cast<long>(o.inputs.size()),
                        [&](long i) { packings[i] = voxel::read_packing(o.inputs[i], {o.scale, o.d0}); });
  for (const auto& p : packings)
    for (std::size_t k = 0; k < deltas.size(); ++k)
      if (deltas[k] * p.d0 > p.box.minCoeff())
        throw UsageError(fmt::format("{}: --delta {} is larger than the box (smallest side {} = {:.4g} D0, D0 = {} from {})",
                                     p.file, delta_names[k], p.box.minCoeff(), p.box.minCoeff() / p.d0,
                                     io::format_number(p.d0), p.d0_source));
  io::AtomicOutput csv_out(o.csv);
  io::CsvWriter csv(csv_out.stream());
  csv.meta("provenance", provenance);
  csv.meta("connectivity", o.connectivity);
  csv.meta("labelling", o.periodic ? "periodic perpendicular to each axis" : "not periodic (scipy.ndimage.label)");
  csv.meta("units", "delta and rh_*_d0 in D0; rh_*_delta in voxel sides (actual spacing); porosity 1 - sum V/V_box");
  bool header = false;
  cli::ProgressBar bar("percolate", static_cast<double>(runs), o.common.quiet);
  std::size_t done = 0;
  for (std::size_t i = 0; i < packings.size(); ++i) {
    const auto& p = packings[i];
    for (std::size_t k = 0; k < deltas.size(); ++k) {
      std::vector<std::uint8_t> cluster;
      const auto a = voxel::analyse_pores(p, deltas[k], ao, o.vtk.empty() ? nullptr : &cluster);
      std::vector<std::pair<std::string, std::string>> fields{
          {"file", p.file},
          {"kind", p.kind == voxel::Packing::Kind::Shells ? "shells" : "spheres"},
          {"particles", std::to_string(p.particles())},
          {"d0", io::format_number(p.d0)},
          {"d0_source", p.d0_source},
          {"scale", io::format_number(p.scale)},
          {"delta", delta_names[k]}};
      for (auto& f : voxel::pore_analysis_fields(a)) fields.push_back(std::move(f));
      if (!header) {
        std::vector<std::string> names;
        for (const auto& f : fields) names.push_back(f.first);
        csv.header(names);
        header = true;
      }
      std::vector<std::string> row;
      for (const auto& f : fields) row.push_back(f.second);
      csv.row(row);
      if (!o.vtk.empty()) {
        io::VoxelImage<std::uint8_t> img;
        img.dims = a.grid.dims;
        img.spacing = a.delta_actual;
        img.origin = 0.5 * a.delta_actual;  // voxel centres, in D0
        img.name = "cluster";
        img.data = std::move(cluster);
        io::write_vtk(vtk_names[i * deltas.size() + k], img,
                      fmt::format("percolating cluster along {} of {} delta={} D0={} ({}) marking={} | {}", o.axis,
                                  p.file, delta_names[k], io::format_number(p.d0), p.d0_source, a.marking, provenance));
      }
      if (!o.common.quiet && !bar.enabled())
        std::cerr << fmt::format("percolate: {} delta={} ({}x{}x{}, D0={} from {}): porosity {:.4f} (voxels {:.4f}), "
                                 "{} clusters, percolates x/y/z {}/{}/{}, R_h {:.4g} D0\n",
                                 p.file, delta_names[k], a.grid.dims[0], a.grid.dims[1], a.grid.dims[2],
                                 io::format_number(p.d0), p.d0_source, a.porosity_geometry, a.porosity_voxels,
                                 a.clusters, int(a.percolates[0]), int(a.percolates[1]), int(a.percolates[2]),
                                 a.rh_faces_d0);
      bar.update(static_cast<double>(++done));
    }
  }
  csv_out.commit();
}

void run_sweep(const Options& o, const std::string& provenance) {
  cli::OptionChecks checks;
  checks.require(o.bins >= 1, fmt::format("--bins must be >= 1, got {}", o.bins));
  checks.throw_if_any();
  std::vector<voxel::PercolationSample> samples;
  for (const auto& path : o.tables) {
    const auto t = io::read_csv(path);
    const int cn = t.column("particles"), cd = t.column("delta"), cp = t.column(o.porosity_column),
              cy = t.column("percolates");
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      voxel::PercolationSample s;
      s.particles = static_cast<int>(t.number(r, cn));
      s.delta = t.number(r, cd);
      s.porosity = t.number(r, cp);
      const double y = t.number(r, cy);
      if (y != 0 && y != 1) throw InputError(path, t.row_lines[r], "percolates must be 0 or 1");
      s.percolates = y == 1;
      samples.push_back(s);
    }
  }
  const auto bins = voxel::percolation_probability(samples, o.bins);
  io::AtomicOutput out(o.csv);
  io::CsvWriter csv(out.stream());
  csv.meta("provenance", provenance);
  csv.meta("porosity", o.porosity_column);
  csv.header({"particles", "delta", "porosity_low", "porosity_high", "porosity_mean", "packings", "percolating",
              "probability", "probability_error"});
  for (const auto& b : bins)
    csv.row({std::to_string(b.particles), io::format_number(b.delta), io::format_number(b.porosity_low),
             io::format_number(b.porosity_high), io::format_number(b.porosity_mean), std::to_string(b.packings),
             std::to_string(b.percolating), io::format_number(b.probability), io::format_number(b.probability_error)});
  out.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return cli::run_tool("percolate", [&] {
    Options o;
    auto app = cli::make_app("percolate",
                             "Pore space of a packing on a lattice of side delta: porosity, connected clusters, "
                             "percolation per axis, hydraulic radius, the percolating cluster as VTK (thesis 5.2.2).");
    app->add_option("packings", o.inputs, "packing OFF files (shells; '# box' needed) or extended XYZ (.xyz: spheres "
                                          "with a radius column); '-' reads an OFF from stdin");
    app->add_option("-d,--delta", o.deltas, "lattice constant(s) delta [D0], comma separated, e.g. 0.03,0.04,0.05");
    app->add_option("--d0", o.d0, "D0, the unit of delta [length units of the file]; default: a 'D0=' comment of the "
                                  "file, else the volume-equivalent diameter of the mean shell (OFF) or the mean "
                                  "unscaled sphere diameter (XYZ); the CSV says which (d0_source)");
    app->add_option("--scale", o.scale, "spheres: multiply every radius by this factor (inflation)")->capture_default_str();
    app->add_option("--marking", o.marking, "shells: 'triangles' (conservative triangle-voxel overlap) or 'vertices' "
                                            "(thesis; leaks when delta < edge length)")->capture_default_str();
    app->add_option("--thickness", o.thickness, "shells: also mark voxels within this max-norm distance of the "
                                                "surface [D0]")->capture_default_str();
    app->add_option("--sphere-marking", o.sphere_marking, "spheres: 'overlap' (any part of the voxel inside) or "
                                                          "'centre' (the voxel centre inside)")->capture_default_str();
    app->add_option("--connectivity", o.connectivity, "neighbours of a void voxel: 6 (faces, scipy's default), 18, 26")
        ->capture_default_str();
    app->add_flag("--periodic", o.periodic, "label with periodic faces perpendicular to the axis tested (as LB's "
                                            "boundaries); default: not periodic, as scipy.ndimage.label in the thesis");
    app->add_option("--axis", o.axis, "flow axis: the cluster written and measured (R_h) spans it")->capture_default_str();
    app->add_option("-o,--output", o.vtk, "percolating cluster as binary VTK STRUCTURED_POINTS (1 = cluster, spacing "
                                          "delta in D0); with several packings or deltas use {name} and {delta}");
    app->add_option("--csv", o.csv, "CSV output, one row per packing and delta ('-': stdout)")->capture_default_str();
    cli::add_threads_option(*app, o.common);
    cli::add_quiet_option(*app, o.common);

    auto* sweep = app->add_subcommand("sweep", "percolation probability vs porosity per N and delta, in porosity bins, "
                                               "from percolate's CSV rows (input of kcfit's sigmoid fit)");
    sweep->add_option("tables", o.tables, "CSV files written by percolate")->required();
    sweep->add_option("--bins", o.bins, "porosity bins per (N, delta) over the range of the data")->capture_default_str();
    sweep->add_option("--porosity", o.porosity_column, "column to bin: porosity_geometry_overlap (spheres: lens-corrected; shells: = porosity_geometry), porosity_geometry (1 - sum V / V_box) or porosity_voxels")
        ->capture_default_str();
    sweep->add_option("-o,--output", o.csv, "output CSV ('-': stdout)")->capture_default_str();

    cli::parse(*app, argc, argv);
    cli::apply_threads(o.common);
    const std::string provenance = cli::provenance("percolate", argc, argv);
    if (sweep->parsed()) {
      run_sweep(o, provenance);
      return 0;
    }
    if (o.deltas.empty()) throw UsageError("--delta is required");
    run_percolate(o, provenance);
    return 0;
  });
}
