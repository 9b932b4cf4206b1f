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
template <class Real>
void FlowSolver::Impl::pressure_node(Real* F, const PressureNode& p, bool after_odd) const {
  const int a = settings.axis, b = (a + 1) % 3, c = (a + 2) % 3;
  double f[kQ];
  std::size_t slots[kQ];
  for (int q = 0; q < kQ; ++q) {
    slots[q] = incoming_slot(q, p.node, after_odd);
    f[q] = load_population(F, slots[q]);
  }
  double level = 0, out = 0, nb = 0, nc = 0;
  for (int q = 0; q < kQ; ++q) {
    const int cn = velocity(q, a) * p.sign;
    if (cn == 0) {
      level += f[q];
      nb += 0.5 * velocity(q, b) * f[q];
      nc += 0.5 * velocity(q, c) * f[q];
    } else if (cn < 0) {
      out += f[q];
    }
  }
  const double jn = p.rho - (level + 2 * out);
  for (int q = 1; q < kQ; ++q) {
    if (velocity(q, a) * p.sign != 1) continue;
    const int cb = velocity(q, b), cc = velocity(q, c);
    const double v = cb == 0 && cc == 0 ? f[opposite(q)] + jn / 3 : f[opposite(q)] + jn / 6 - cb * nb - cc * nc;
    store_population(F, slots[q], v);
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
    const long end = chunk_begin(n_open, open_chunks, c + 1);
    for (long i = chunk_begin(n_open, open_chunks, c); i < end; ++i) pressure_node(F, open[static_cast<std::size_t>(i)], after_odd);
  });
}

template void FlowSolver::Impl::apply_pressure_planes<double>(double*, bool) const;
template void FlowSolver::Impl::apply_pressure_planes<float>(float*, bool) const;

}  // namespace cmp::lbm
