#pragma once
// The runs of percolate (thesis 5.2.2, 5.3.1-5.3.2): every packing (each frame of each input
// file) at every radius scale and every delta, in that order, each giving one CSV row, the
// percolating cluster as a VTK image when asked for, and a summary line for stderr.
#include "io/csv.hpp"
#include "io/vtk.hpp"
#include "packing/packing_file.hpp"
#include "voxel/pore_analysis.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cmp::voxel {

// The packings of the input files, frame by frame: an OFF gives one, an extended XYZ one per
// frame (frame 0, 1, ... as ASE and OVITO count them).
struct PackingFrames {
  std::vector<packing::Packing> packings;     // input after input, frame after frame
  std::vector<std::size_t> input_of;  // per packing: its index in the list of inputs
  std::vector<int> frame_of;          // per packing: its frame in that input
  bool several_frames = false;        // some input holds more than one frame
};

// Reads every input with read_packings (one job per input, in parallel) before anything is
// analysed, so a bad file stops percolate before any output is written. Throws what
// read_packings throws (the error of the first bad input in the list).
PackingFrames read_packing_frames(const std::vector<std::string>& inputs, const packing::PackingReadOptions& options);

// One run: a packing at one radius scale and one delta (indices into the lists).
struct PercolateRun {
  std::size_t packing = 0, scale = 0, delta = 0;
};

// The runs of packings x scales x deltas, packings outermost, then scales, then deltas (the
// order of the CSV rows and of the -o files alike).
std::vector<PercolateRun> percolate_runs(std::size_t packings, std::size_t scales, std::size_t deltas);

// What the options ask for, checked by the tool: the analysis and the lists, with each
// number's token as typed (it names the run in messages, titles, the CSV and {delta}).
struct PercolatePlan {
  PoreAnalysisOptions analysis;
  std::vector<double> deltas, scales;            // [D_0], radius factors; positive
  std::vector<std::string> delta_names, scale_names;
  std::string axis_name = "x";                   // --axis as typed (the VTK title)
  std::string connectivity_name = "6";           // --connectivity as typed (the CSV meta)
  bool images = false;                           // the percolating clusters are wanted (-o)
  bool timings = false;                          // summaries give marking and labelling times
  std::string provenance;                        // the tool, version and command line
};

// Checks plan's lists against the packings read. Throws cmp::UsageError naming the file for:
// a --scale other than 1 given with a packing of shells (it scales spheres only); a --delta
// whose voxel side delta * D_0 is larger than the box's smallest side.
void check_percolate_plan(const std::vector<packing::Packing>& packings, const PercolatePlan& plan);

// What one run gives.
struct PercolateRunResult {
  std::vector<std::string> columns, row;  // the CSV row: file, frame, kind, ..., then pore_analysis_fields
  io::VoxelImage<std::uint8_t> image;     // plan.images: 1 = percolating cluster (name "cluster"),
                                          // origin and spacing in the packing's length units,
                                          // field data delta, d0, scale; else empty
  std::string title;                      // plan.images: the VTK title (ends with the provenance)
  std::string summary;                    // the stderr line, without the "percolate: " prefix
};

// Called after each run, in order: r indexes runs; result may be moved from.
using PercolateRunSink = std::function<void(std::size_t r, PercolateRunResult& result)>;

// Runs analyse_pores over runs (from percolate_runs over frames.packings) with plan, the radii
// of sphere packings multiplied by the run's scale, and hands each result to sink. Returns the
// warning for runs whose pair-lens porosity is an upper bound, not exact (counted once per
// packing and scale, the first three named), without the "percolate: " prefix; empty when
// every porosity is exact. Throws what analyse_pores and sink throw.
std::string run_percolate(const PackingFrames& frames, const PercolatePlan& plan,
                          const std::vector<PercolateRun>& runs, const PercolateRunSink& sink);

// Writes the meta lines of percolate's CSV (provenance, connectivity, labelling, porosity,
// units) and then the header columns (PercolateRunResult::columns).
void write_percolate_csv_header(io::CsvWriter& csv, const PercolatePlan& plan, const std::vector<std::string>& columns);

}  // namespace cmp::voxel
