#pragma once
// The jobs of jam2d's periodic box (thesis Chapter 3; docs/jam2d.md): `grow` (one colony to
// jamming and beyond, its table, packing and trajectory), `moduli` (of packings read from
// files) and `sweep` (many seeds in parallel, one table). The chamber's are in chamber_job.hpp.
#include "cells2d/colony.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cmp::cells2d {

struct GrowJob {
  GrowthParameters growth;
  std::uint64_t seed = 1;
  double dphi = 0;                        // grow beyond jamming to phi_J + dphi
  std::string packing, csv = "-", trajectory;  // outputs ('' for none, '-' stdout)
  long every = 1;                         // accepted steps between trajectory frames
  bool quiet = false;
  std::string provenance;
};
void run_grow_job(const GrowJob& job);

struct ModuliJob {
  std::vector<std::string> inputs;
  std::string output = "-", contact = "harmonic";
  std::string provenance;
};
void run_moduli_job(const ModuliJob& job);

struct SweepJob {
  GrowthParameters growth;
  std::vector<std::uint64_t> seeds;
  std::vector<double> dphis, P0s;
  std::string output = "-";
  bool quiet = false;
  std::string provenance;
};
void run_sweep_job(const SweepJob& job);

}  // namespace cmp::cells2d
