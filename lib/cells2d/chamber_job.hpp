#pragma once
// The jobs of `jam2d chamber` and `jam2d avalanches` (docs/jam2d.md): a chamber run sampled into
// its time series and trajectory, checkpointed and resumable, and the avalanche analysis of a
// series.
#include "cells2d/chamber.hpp"

#include <cstdint>
#include <string>

namespace cmp::cells2d {

struct ChamberJob {
  ChamberParameters parameters;
  std::uint64_t seed = 1;
  double duration = 100;       // simulated time [1/gamma0]
  double sample_every = 0.01;  // between rows
  double frame_every = 1;      // between trajectory frames
  std::string csv = "-", trajectory;
  // Resumable runs: the state, the rows and the frames so far are saved every checkpoint_every
  // seconds (wall clock) at a row's time, and at the end; --resume continues from the file
  // with the same parameters (--time may be longer), and ends with the same bytes as a run
  // never stopped.
  std::string checkpoint, resume;
  double checkpoint_every = 60;
  double stop_after = -1;      // stop (checkpoint, no outputs) at this simulated time; tests
  bool quiet = false;
  std::string provenance;
};

void run_chamber_job(const ChamberJob& job);

struct AvalancheJob {
  std::string input, output = "-", distribution;
  std::string pressure_column = "pressure_walls";
  double merge = 0.05, from = -1;
  std::string provenance;
};

void run_avalanche_job(const AvalancheJob& job);

}  // namespace cmp::cells2d
