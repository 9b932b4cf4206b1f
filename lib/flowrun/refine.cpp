#include "flowrun/refine.hpp"

#include <stdexcept>

namespace cmp::flowrun {

std::vector<std::uint8_t> refine_mask(const std::vector<std::uint8_t>& mask, std::array<int, 3> dims, int M) {
  if (M < 1) throw std::invalid_argument("refine_mask: M must be at least 1");
  if (mask.size() != static_cast<std::size_t>(dims[0]) * dims[1] * dims[2])
    throw std::invalid_argument("refine_mask: mask size differs from dims");
  const long long nx = 1LL * dims[0] * M, ny = 1LL * dims[1] * M, nz = 1LL * dims[2] * M;
  if (static_cast<unsigned long long>(nx) * ny * nz > (1ULL << 40))
    throw std::invalid_argument("refine_mask: more than 2^40 nodes");
  std::vector<std::uint8_t> out(static_cast<std::size_t>(nx * ny * nz));
#pragma omp parallel for schedule(static)
  for (long long z = 0; z < nz; ++z)
    for (long long y = 0; y < ny; ++y) {
      const std::uint8_t* row = mask.data() + static_cast<std::size_t>(dims[0]) * (y / M + 1LL * dims[1] * (z / M));
      std::uint8_t* dst = out.data() + static_cast<std::size_t>(nx * (y + ny * z));
      for (long long x = 0; x < nx; ++x) dst[x] = row[x / M];
    }
  return out;
}

}  // namespace cmp::flowrun
