// The pressure planes (FlowSettings::kPressure): Zou-He pressure nodes on the fluid nodes of
// the first and last planes along the flow axis, applied after each sweep.
#include "lbm/flow_solver_state.hpp"

namespace cmp::lbm {

// Zou & He (1997) pressure node, in the D3Q19 form of Hecht & Harting (2010): from the
// imposed density and the known populations (those not arriving from outside the box),
// the normal momentum j_n = rho_b - (sum_{c.n=0} f + 2 sum_{c.n=-1} f); each unknown
// population (c.n = +1) is its opposite plus the equilibrium difference, j_n/3 (face) or
// j_n/6 (edge), minus the transverse correction c_t N_t, N_t = 1/2 sum_{c.n=0} f c_t, that
// zeroes the tangential momentum (the pressure planes carry no tangential velocity).
namespace {

// One pressure node on the plane whose inward normal is S * axis A (S = +1: inlet, -1:
// outlet). A and S are template constants, so every test of a direction's components below
// is decided at compile time and the loops unroll to straight code (with the axis and side
// read at run time, the pass over bench_lbm's porous 128^3 box, 10 378 nodes, took 0.38 ms
// on one thread, 37 ns per node and ~4 % of a step; now 0.13 ms). The sums run over q in the
// same order either way, so the bits are the same.
template <int A, int S, class Real>
void pressure_node(Real* F, const std::size_t (&slots)[kQ], double rho) {
  constexpr int B = (A + 1) % 3, C = (A + 2) % 3;
  double f[kQ];
#pragma GCC unroll 19
  for (int q = 0; q < kQ; ++q) f[q] = load_population(F, slots[q]);
  double level = 0, out = 0, nb = 0, nc = 0;
#pragma GCC unroll 19
  for (int q = 0; q < kQ; ++q) {
    const int cn = velocity(q, A) * S;
    if (cn == 0) {
      level += f[q];
      nb += 0.5 * velocity(q, B) * f[q];
      nc += 0.5 * velocity(q, C) * f[q];
    } else if (cn < 0) {
      out += f[q];
    }
  }
  const double jn = rho - (level + 2 * out);
#pragma GCC unroll 18
  for (int q = 1; q < kQ; ++q) {
    if (velocity(q, A) * S != 1) continue;
    const int cb = velocity(q, B), cc = velocity(q, C);
    const double v = cb == 0 && cc == 0 ? f[opposite(q)] + jn / 3 : f[opposite(q)] + jn / 6 - cb * nb - cc * nc;
    store_population(F, slots[q], v);
  }
}

}  // namespace

// Nodes [begin, end) of `open`, on the planes normal to axis A.
template <int A, class Real>
void FlowSolver::Impl::pressure_nodes(Real* F, long begin, long end, bool after_odd) const {
  for (long i = begin; i < end; ++i) {
    const PressureNode& p = open[static_cast<std::size_t>(i)];
    std::size_t slots[kQ];
#pragma GCC unroll 19
    for (int q = 0; q < kQ; ++q) slots[q] = incoming_slot(q, p.node, after_odd);
    if (p.sign > 0) pressure_node<A, 1>(F, slots, p.rho);
    else pressure_node<A, -1>(F, slots, p.rho);
  }
}

// Each node touches only its own slots. The planes are cut into fixed chunks over the threads
// (same bits for any thread count): in the bench's porous 128^3 box their ~11 000 nodes took
// 1.4 ms of a 15.5 ms step on one thread while the other waited.
template <class Real>
void FlowSolver::Impl::apply_pressure_planes(Real* F, bool after_odd) const {
  const long n_open = static_cast<long>(open.size());
  const int open_chunks = n_open >= 256 ? 8 : 1;
  for_each_chunk(open_chunks, [&](int c) {
    const long begin = chunk_begin(n_open, open_chunks, c), end = chunk_begin(n_open, open_chunks, c + 1);
    switch (settings.axis) {
      case 0: pressure_nodes<0>(F, begin, end, after_odd); break;
      case 1: pressure_nodes<1>(F, begin, end, after_odd); break;
      default: pressure_nodes<2>(F, begin, end, after_odd); break;
    }
  });
}

template void FlowSolver::Impl::apply_pressure_planes<double>(double*, bool) const;
template void FlowSolver::Impl::apply_pressure_planes<float>(float*, bool) const;

}  // namespace cmp::lbm
