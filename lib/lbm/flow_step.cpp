// One fused stream+collide AA step (lbm/flow_solver.hpp): the collision operator's sweep over
// the fixed node chunks on all threads, the halo exchange with the neighbouring ranks, then the
// boundary passes.
#include "lbm/flow_solver_state.hpp"

#include "core/thread_governor.hpp"

#include <chrono>

namespace cmp::lbm {

template <class Real>
void FlowSolver::Impl::step_once() {
  BigVector<Real>& F = pops<Real>();
  const bool odd = (steps & 1) != 0;
  const double* g = settings.driving == Driving::kBodyForce ? force : nullptr;
  for_each_chunk(chunks, [&](int c) {
    SweepRange<Real> r{F.data(), links.data(), chunk_start(c), chunk_start(c + 1), odd, g,
                       chunk_consecutive[static_cast<std::size_t>(c)] ? consecutive.data() : nullptr};
    op->sweep(r);
  });
  // The halo before the boundary passes, which read ghost slots (lbm/halo_exchange.hpp).
  if (!halo.empty()) {  // (timed for lbflow --timings; one process has no halo and no clock call)
    const auto start = std::chrono::steady_clock::now();
    if (odd) halo.return_ghosts(F.data());
    else halo.fill_ghosts(F.data());
    halo_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  apply_pressure_planes(F.data(), odd);
  apply_walls(F.data(), odd);
  ++steps;
}

void FlowSolver::step(long n) {
  if (n <= 0) return;
  // The governor's iteration is a pair of steps: an odd step costs about twice an even one, so
  // a one-step probe compared one parity with the average of both (on the thesis-sized lattice
  // one-thread probes read 6 or 20 steps/s against 21 on two threads, nearly switching).
  ThreadGovernor governor;
  for (long k = 0; k < n; ++k) {
    if (impl_->settings.precision == Precision::kFloat) impl_->step_once<float>();
    else impl_->step_once<double>();
    if ((impl_->steps & 1) == 0) governor.tick();
  }
}

}  // namespace cmp::lbm
