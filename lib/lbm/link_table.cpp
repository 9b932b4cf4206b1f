// The fluid nodes' numbering and the link table (lbm/flow_solver.hpp): which slot each
// population leaving a node goes to.
#include "lbm/flow_solver_state.hpp"

#include "lbm/sweep_kernel.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <bit>
#include <string>

namespace cmp::lbm {

std::vector<WallFraction> FlowSolver::Impl::build_link_table(const PoreLattice& lattice) {
  const int a = settings.axis;
  const bool pressure = settings.driving == Driving::kPressure;

  // Number the fluid nodes brick by brick: bricks of kBrickPlanes planes along the axis and
  // brick_rows() rows across it, in each brick plane by plane and row by row (lbm/layout.hpp).
  const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;  // the other two axes, lower first (fastest)
  const int rows = brick_rows(n[b]);
  std::vector<long> node_of(static_cast<std::size_t>(lattice.nodes()), -1);
  for (int s0 = 0; s0 < n[a]; s0 += kBrickPlanes)
    for (int v0 = 0; v0 < n[c]; v0 += rows)
      for (int s = s0; s < std::min(n[a], s0 + kBrickPlanes); ++s)
        for (int v = v0; v < std::min(n[c], v0 + rows); ++v)
          for (int u = 0; u < n[b]; ++u) {
            int xyz[3];
            xyz[a] = s;
            xyz[b] = u;
            xyz[c] = v;
            const long i = lattice.index(xyz[0], xyz[1], xyz[2]);
            if (!lattice.fluid[static_cast<std::size_t>(i)]) continue;
            node_of[static_cast<std::size_t>(i)] = static_cast<long>(site.size());
            site.push_back(i);
          }
  fluid = static_cast<long>(site.size());
  if (fluid == 0) throw UsageError("pore lattice has no fluid node");
  stride = (fluid + kBatch - 1) / kBatch * kBatch;
  if (static_cast<double>(stride) * kQ >= 4294967295.0)
    throw UsageError("pore lattice too large: " + std::to_string(fluid) + " fluid nodes (at most 2^32/19)");
  chunks = static_cast<int>(std::clamp<long>(stride / (kBatch * 256), 1, 64));

  // Link table and boundary lists.
  const long N = stride;
  // kPrefetchAhead blocks of padding (slot 0) for the odd sweep's prefetches past the end.
  links.assign(static_cast<std::size_t>(18 * (N + kernel::kPrefetchAhead * kBatch)), 0);
  auto slot = [](int q, long node) { return static_cast<std::uint32_t>(pop_slot(q, node)); };
  const double rho_in = 1 + 0.5 * settings.density_drop, rho_out = 1 - 0.5 * settings.density_drop;
  std::vector<WallFraction> pending;
  for (long i = 0; i < N; ++i) {
    if (i >= fluid) {  // padding: an isolated node that bounces everything back
      for (int q = 1; q < kQ; ++q) links[link_index(q, i)] = slot(opposite(q), i);
      continue;
    }
    const long g = site[static_cast<std::size_t>(i)];
    const int x = static_cast<int>(g % n[0]), y = static_cast<int>(g / n[0] % n[1]), z = static_cast<int>(g / n[0] / n[1]);
    const int xyz[3] = {x, y, z};
    if (pressure && (xyz[a] == 0 || xyz[a] == n[a] - 1))
      open.push_back({i, xyz[a] == 0 ? 1 : -1, xyz[a] == 0 ? rho_in : rho_out});
    for (int q = 1; q < kQ; ++q) {
      int t[3] = {x + kCx[q], y + kCy[q], z + kCz[q]};
      bool outside = false;
      for (int d = 0; d < 3; ++d) {
        if (pressure && d == a && (t[d] < 0 || t[d] >= n[d])) outside = true;
        t[d] = (t[d] % n[d] + n[d]) % n[d];
      }
      std::uint32_t& link = links[link_index(q, i)];
      if (outside) {  // bounced back, then replaced by the pressure node pass
        link = slot(opposite(q), i);
        continue;
      }
      const long j = node_of[static_cast<std::size_t>(lattice.index(t[0], t[1], t[2]))];
      if (j >= 0) {
        link = slot(q, j);
      } else {
        link = slot(opposite(q), i);
        ++wall_links;
        if (lattice.wall_fraction) {
          const double fr = lattice.wall_fraction(x, y, z, q);
          if (!(fr > 0 && fr <= 1))
            throw UsageError("wall fraction must lie in (0, 1], got " + std::to_string(fr));
          if (fr != 0.5) pending.push_back({i, q, fr});
        }
      }
    }
  }
  // Lines the odd sweep may move as one vector, used by the chunks where they are common
  // (below a quarter of the lines the branch costs more than they save: lbm/sweep_kernel.hpp).
  constexpr double kMinConsecutiveShare = 0.25;
  consecutive.resize(static_cast<std::size_t>(N / kBatch));
  for (long block = 0; block < N / kBatch; ++block)
    consecutive[static_cast<std::size_t>(block)] = consecutive_lines(links.data(), block * kBatch);
  chunk_consecutive.assign(static_cast<std::size_t>(chunks), 0);
  for (int c = 0; c < chunks; ++c) {
    long lines = 0, moved = 0;
    for (long block = chunk_start(c) / kBatch; block < chunk_start(c + 1) / kBatch; ++block) {
      lines += kQ - 1;
      moved += std::popcount(consecutive[static_cast<std::size_t>(block)]);
    }
    chunk_consecutive[static_cast<std::size_t>(c)] = moved >= kMinConsecutiveShare * static_cast<double>(lines);
  }
  if (std::find(chunk_consecutive.begin(), chunk_consecutive.end(), 1) == chunk_consecutive.end())
    std::vector<std::uint32_t>().swap(consecutive);
  return pending;
}

}  // namespace cmp::lbm
