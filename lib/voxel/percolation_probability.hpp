#pragma once
// Percolation probability versus porosity (thesis Fig. 5.2B, C): the fraction of packings
// whose void percolates, in porosity bins, for each system size N and lattice size delta.
// The input of kcfit's sigmoid and threshold fits (Fig. 5.2 C-D).
#include <vector>

namespace cmp::voxel {

struct PercolationSample {
  int particles = 0;   // N
  double delta = 0;    // requested delta [D_0]
  double porosity = 0;
  bool percolates = false;
};

struct ProbabilityBin {
  int particles = 0;
  double delta = 0;
  double porosity_low = 0, porosity_high = 0;  // bin edges
  double porosity_mean = 0;                     // mean porosity of the packings in the bin
  int packings = 0, percolating = 0;
  double probability = 0;                       // percolating / packings
  double probability_error = 0;                 // binomial standard error sqrt(p(1-p)/n)
};

// Groups samples by (particles, delta), sorted ascending, and cuts each group's porosity
// range [min, max] into `bins` equal bins (the last one closed); empty bins are left out.
// A group whose porosities are all equal gives one bin. Throws std::invalid_argument for
// bins < 1.
std::vector<ProbabilityBin> percolation_probability(const std::vector<PercolationSample>& samples, int bins);

}  // namespace cmp::voxel
