// The fluid nodes' numbering and the link table (lbm/flow_solver.hpp): which slot each
// population leaving a node goes to.
#include "lbm/flow_solver_state.hpp"

#include "lbm/sweep_kernel.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <bit>
#include <memory>
#include <stdexcept>
#include <string>

namespace cmp::lbm {

std::vector<WallFraction> FlowSolver::Impl::build_link_table(const PoreLattice& lattice) {
  const int a = settings.axis;
  const bool pressure = settings.driving == Driving::kPressure;
  const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;  // the other two axes, lower first (fastest)
  const auto plane_of = [&](long i) {
    return static_cast<int>(a == 0 ? i % n[0] : a == 1 ? i / n[0] % n[1] : i / n[0] / n[1]);
  };

  // This rank's slabs: cut by their fluid nodes (lbm/slab_decomposition.hpp).
  std::vector<long> slab_fluid(static_cast<std::size_t>(slab_count(n[a])), 0);
  for (long i = 0; i < lattice.nodes(); ++i)
    if (lattice.fluid[static_cast<std::size_t>(i)]) ++slab_fluid[static_cast<std::size_t>(plane_of(i) / kBrickPlanes)];
  for (long f : slab_fluid) global_fluid += f;
  if (global_fluid == 0) throw UsageError("pore lattice has no fluid node");
  decomposition = decompose_slabs(slab_fluid, comm.size());
  first_slab = decomposition.first_slab[static_cast<std::size_t>(comm.rank())];
  const int end_slab = decomposition.first_slab[static_cast<std::size_t>(comm.rank()) + 1];
  for (int k = 0; k < first_slab; ++k) first_node += slab_fluid[static_cast<std::size_t>(k)];
  const int p0 = first_slab * kBrickPlanes, p1 = std::min(n[a], end_slab * kBrickPlanes);
  // The planes just outside them (across the periodic ends with body-force driving), unless own.
  std::vector<int> ghost_planes;
  const auto add_ghost = [&](int p) {
    if ((p < p0 || p >= p1) && std::find(ghost_planes.begin(), ghost_planes.end(), p) == ghost_planes.end())
      ghost_planes.push_back(p);
  };
  if (p0 > 0 || !pressure) add_ghost((p0 - 1 + n[a]) % n[a]);
  if (p1 < n[a] || !pressure) add_ghost(p1 % n[a]);
  // Local node of each site of the own and ghost planes (-1: solid).
  const long plane_sites = static_cast<long>(n[b]) * n[c];
  std::vector<long> node_of(static_cast<std::size_t>((p1 - p0 + static_cast<long>(ghost_planes.size())) * plane_sites), -1);
  const auto local_index = [&](int p, int u, int v) -> long {  // index into node_of, or -1
    long lp = -1;
    if (p >= p0 && p < p1) lp = p - p0;
    for (std::size_t k = 0; k < ghost_planes.size(); ++k)
      if (ghost_planes[k] == p) lp = p1 - p0 + static_cast<long>(k);
    return lp < 0 ? -1 : (lp * n[c] + v) * n[b] + u;
  };
  const auto node_at = [&](const int (&t)[3]) -> long {
    const long k = local_index(t[a], t[b], t[c]);
    return k < 0 ? -1 : node_of[static_cast<std::size_t>(k)];
  };

  // Number the own fluid nodes brick by brick: bricks of kBrickPlanes planes along the axis and
  // brick_rows() rows across it, in each brick plane by plane and row by row (lbm/layout.hpp).
  const int rows = brick_rows(n[b]);
  for (int s0 = p0; s0 < p1; s0 += kBrickPlanes) {
    slab_start.push_back(static_cast<long>(site.size()));
    for (int v0 = 0; v0 < n[c]; v0 += rows)
      for (int s = s0; s < std::min(p1, s0 + kBrickPlanes); ++s)
        for (int v = v0; v < std::min(n[c], v0 + rows); ++v)
          for (int u = 0; u < n[b]; ++u) {
            int xyz[3];
            xyz[a] = s;
            xyz[b] = u;
            xyz[c] = v;
            const long i = lattice.index(xyz[0], xyz[1], xyz[2]);
            if (!lattice.fluid[static_cast<std::size_t>(i)]) continue;
            node_of[static_cast<std::size_t>(local_index(s, u, v))] = static_cast<long>(site.size());
            site.push_back(i);
          }
  }
  slab_start.push_back(static_cast<long>(site.size()));
  fluid = static_cast<long>(site.size());
  stride = (fluid + kBatch - 1) / kBatch * kBatch;
  // Then the ghost nodes, plane by plane.
  for (int p : ghost_planes)
    for (int v = 0; v < n[c]; ++v)
      for (int u = 0; u < n[b]; ++u) {
        int xyz[3];
        xyz[a] = p;
        xyz[b] = u;
        xyz[c] = v;
        const long i = lattice.index(xyz[0], xyz[1], xyz[2]);
        if (!lattice.fluid[static_cast<std::size_t>(i)]) continue;
        node_of[static_cast<std::size_t>(local_index(p, u, v))] = stride + static_cast<long>(ghost_site.size());
        ghost_site.push_back(i);
      }
  ghost_end = stride + (static_cast<long>(ghost_site.size()) + kBatch - 1) / kBatch * kBatch;
  if (static_cast<double>(ghost_end) * kQ >= 4294967295.0)
    throw UsageError("pore lattice too large: " + std::to_string(fluid) + " fluid nodes on one process (at most 2^32/19)" +
                     (comm.size() > 1 || !Communicator::built_with_mpi() ? "" : ": run it on several MPI ranks"));
  chunks = static_cast<int>(std::clamp<long>(stride / (kBatch * 256), 1, 64));

  // Link table and boundary lists.
  const long N = stride;
  // kPrefetchAhead blocks of padding (slot 0) for the odd sweep's prefetches past the end.
  links.assign(static_cast<std::size_t>(18 * (ghost_end + kernel::kPrefetchAhead * kBatch)), 0);
  auto slot = [](int q, long node) { return static_cast<std::uint32_t>(pop_slot(q, node)); };
  const double rho_in = 1 + 0.5 * settings.density_drop, rho_out = 1 - 0.5 * settings.density_drop;
  std::vector<WallFraction> pending;
  std::vector<GhostSlot> ghost_slots;
  const long ghosts = static_cast<long>(ghost_site.size());
  for (long i = 0; i < ghost_end; ++i) {
    const bool ghost = i >= N && i - N < ghosts;
    if ((i >= fluid && i < N) || (i >= N && !ghost)) {  // padding: an isolated node that bounces everything back
      for (int q = 1; q < kQ; ++q) links[link_index(q, i)] = slot(opposite(q), i);
      continue;
    }
    const long g = ghost ? ghost_site[static_cast<std::size_t>(i - N)] : site[static_cast<std::size_t>(i)];
    const int x = static_cast<int>(g % n[0]), y = static_cast<int>(g / n[0] % n[1]), z = static_cast<int>(g / n[0] / n[1]);
    const int xyz[3] = {x, y, z};
    if (!ghost && pressure && (xyz[a] == 0 || xyz[a] == n[a] - 1))
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
      const long j = node_at(t);
      if (ghost) {  // a ghost is never swept: its links serve the wall pass's look-ups only
        link = j >= 0 ? slot(q, j) : slot(opposite(q), i);
        continue;
      }
      if (j >= 0) {
        link = slot(q, j);
        if (j >= N)
          ghost_slots.push_back({decomposition.owner(t[a] / kBrickPlanes), lattice.index(t[0], t[1], t[2]), q, link});
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
  // For the halo (built after every rank has allocated, lbm/flow_solver.cpp): this rank's slot
  // of one of its nodes, by site.
  auto own = std::make_shared<std::vector<long>>(std::move(node_of));
  const int lo = p0, hi = p1, nb = n[b], nc = n[c], nx = n[0], ny = n[1];
  own_slot = [own, lo, hi, a, b, c, nb, nc, nx, ny](long g, int q) {
    const int t[3] = {static_cast<int>(g % nx), static_cast<int>(g / nx % ny), static_cast<int>(g / nx / ny)};
    if (t[a] < lo || t[a] >= hi) throw std::logic_error("halo: a slot asked of a rank that does not own it");
    const long node = (*own)[static_cast<std::size_t>((static_cast<long>(t[a] - lo) * nc + t[c]) * nb + t[b])];
    return static_cast<std::uint32_t>(pop_slot(q, node));
  };
  pending_ghosts = std::move(ghost_slots);
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
