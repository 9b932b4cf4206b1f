#include "voxel/percolate_run.hpp"

#include "core/errors.hpp"
#include "core/parallel_for.hpp"

#include <fmt/format.h>

#include <utility>

namespace cmp::voxel {

PackingFrames read_packing_frames(const std::vector<std::string>& inputs, const packing::PackingReadOptions& options) {
  std::vector<std::vector<packing::Packing>> per_input(inputs.size());
  parallel_for_each_job(static_cast<long>(inputs.size()),
                        [&](long i) { per_input[i] = packing::read_packings(inputs[i], options); });
  PackingFrames frames;
  for (std::size_t i = 0; i < per_input.size(); ++i) {
    frames.several_frames |= per_input[i].size() > 1;
    for (std::size_t f = 0; f < per_input[i].size(); ++f) {
      frames.packings.push_back(std::move(per_input[i][f]));
      frames.input_of.push_back(i);
      frames.frame_of.push_back(static_cast<int>(f));
    }
  }
  return frames;
}

std::vector<PercolateRun> percolate_runs(std::size_t packings, std::size_t scales, std::size_t deltas) {
  std::vector<PercolateRun> runs;
  for (std::size_t i = 0; i < packings; ++i)
    for (std::size_t s = 0; s < scales; ++s)
      for (std::size_t k = 0; k < deltas; ++k) runs.push_back({i, s, k});
  return runs;
}

void check_percolate_plan(const std::vector<packing::Packing>& packings, const PercolatePlan& plan) {
  for (const auto& p : packings) {
    if (p.kind == packing::Packing::Kind::Shells)
      for (std::size_t s = 0; s < plan.scales.size(); ++s)
        if (plan.scales[s] != 1)
          throw UsageError(fmt::format("{}: --scale {} applies to sphere packings (extended XYZ) only; this is a "
                                       "packing of shells", p.file, plan.scale_names[s]));
    if (p.kind == packing::Packing::Kind::Spheres)
      for (std::size_t s = 0; s < plan.scales.size(); ++s) packing::check_scale(p, plan.scales[s], plan.scale_names[s]);
    for (std::size_t k = 0; k < plan.deltas.size(); ++k)
      if (plan.deltas[k] * p.d0 > p.box.minCoeff())
        throw UsageError(fmt::format("{}: --delta {} is larger than the box (smallest side {} = {:.4g} D0, D0 = {} from {})",
                                     p.file, plan.delta_names[k], p.box.minCoeff(), p.box.minCoeff() / p.d0,
                                     io::format_number(p.d0), p.d0_source));
  }
}

std::string run_percolate(const PackingFrames& frames, const PercolatePlan& plan,
                          const std::vector<PercolateRun>& runs, const PercolateRunSink& sink) {
  std::vector<std::string> inexact;
  long inexact_runs = 0;
  packing::Packing scaled;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& run = runs[r];
    if (r == 0 || runs[r - 1].packing != run.packing || runs[r - 1].scale != run.scale) {
      scaled = frames.packings[run.packing];
      if (scaled.kind == packing::Packing::Kind::Spheres) {
        scaled.radii *= plan.scales[run.scale];
        scaled.scale = plan.scales[run.scale];
      }
    }
    const auto& p = scaled;
    const auto& scale_name = plan.scale_names[run.scale];
    const auto& delta_name = plan.delta_names[run.delta];
    std::vector<std::uint8_t> cluster;
    const auto a = analyse_pores(p, plan.deltas[run.delta], plan.analysis, plan.images ? &cluster : nullptr);
    if (run.delta == 0 && !a.geometry.exact) {
      ++inexact_runs;
      if (inexact.size() < 3)
        inexact.push_back(fmt::format("{} at scale {}: {} triples of spheres share a point, {} spheres or pairs "
                                      "overlap through a periodic image", p.file, scale_name,
                                      a.geometry.triple_overlaps, a.geometry.image_overlaps));
    }
    std::vector<std::pair<std::string, std::string>> fields{
        {"file", p.file},
        {"frame", std::to_string(frames.frame_of[run.packing])},
        {"kind", p.kind == packing::Packing::Kind::Shells ? "shells" : "spheres"},
        {"particles", std::to_string(p.particles())},
        {"d0", io::format_number(p.d0)},
        {"d0_source", p.d0_source},
        {"scale", io::format_number(p.scale)},
        {"delta", delta_name}};
    for (auto& f : pore_analysis_fields(a)) fields.push_back(std::move(f));
    PercolateRunResult result;
    for (auto& f : fields) {
      result.columns.push_back(std::move(f.first));
      result.row.push_back(std::move(f.second));
    }
    if (plan.images) {
      auto& img = result.image;
      img.dims = a.grid.dims;
      img.spacing = a.grid.spacing;       // in the packing's own length units, so the cluster
      img.origin = 0.5 * a.grid.spacing;  // overlays the packing; points at the voxel centres
      img.name = "cluster";
      img.data = std::move(cluster);
      // What lbflow and a ParaView user need to put the image back in D0 units, and the
      // geometric porosity lbflow's rows carry on to kcfit (the image holds the cluster only).
      img.field_data = {{"delta", plan.deltas[run.delta]}, {"d0", p.d0}, {"scale", p.scale},
                        {"porosity", a.geometry.porosity}};
      result.title = fmt::format("percolating cluster along {} of {} scale={} delta={} D0={} ({}) marking={} "
                                 "(lengths in the packing's units) | {}",
                                 plan.axis_name, p.file, scale_name, delta_name, io::format_number(p.d0),
                                 p.d0_source, a.marking, plan.provenance);
    }
    result.summary = fmt::format(
        "{} scale={} delta={} ({}x{}x{}, D0={} from {}): porosity {:.4f} ({}{}), voxels {:.4f}, "
        "{} clusters, percolates x/y/z {}/{}/{}, R_h {:.4g} D0",
        p.file, scale_name, delta_name, a.grid.dims[0], a.grid.dims[1], a.grid.dims[2], io::format_number(p.d0),
        p.d0_source, a.geometry.porosity, a.geometry.method, a.geometry.exact ? "" : ", upper bound",
        a.porosity_voxels, a.clusters, int(a.percolates[0]), int(a.percolates[1]), int(a.percolates[2]),
        a.rh_faces_d0);
    if (plan.timings)
      result.summary += fmt::format("; marking {:.3f} s, labelling {:.3f} s", a.seconds_marking, a.seconds_labelling);
    sink(r, result);
  }
  if (inexact_runs == 0) return {};
  std::string list;
  for (const auto& s : inexact) list += (list.empty() ? "" : "; ") + s;
  return fmt::format("warning: the pair-lens porosity is an upper bound, not exact, in {} packing/scale run(s) "
                     "(porosity_exact = 0): {}{}",
                     inexact_runs, list, inexact_runs > static_cast<long>(inexact.size()) ? "; ..." : "");
}

void write_percolate_csv_header(io::CsvWriter& csv, const PercolatePlan& plan, const std::vector<std::string>& columns) {
  csv.meta("provenance", plan.provenance);
  csv.meta("connectivity", plan.connectivity_name);
  csv.meta("labelling", plan.analysis.periodic_perpendicular ? "periodic perpendicular to each axis"
                                                             : "not periodic (scipy.ndimage.label)");
  csv.meta("porosity", "geometric, without voxels: porosity_method shell_volumes = 1 - sum of shell volumes / "
                       "V_box; sphere_pair_lenses = 1 - (sum of sphere volumes - pair lenses) / V_box, exact where "
                       "porosity_exact = 1, else an upper bound; porosity_voxels = void voxels / voxels");
  csv.meta("units", "delta, delta_*_d0 and rh_*_d0 in D0; rh_*_delta in voxel sides (actual spacing); VTK origin "
                    "and spacing in the packing's length units");
  csv.header(columns);
}

}  // namespace cmp::voxel
