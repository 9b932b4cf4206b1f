// BGK (single relaxation time): every moment relaxes at 1/tau. The bounce-back wall moves
// with tau (the permeability of a given image depends on the viscosity): kept for comparison.
#include "lbm/collision_styles.hpp"
#include "lbm/sweep_kernel.hpp"

namespace cmp::lbm {

namespace {

struct BgkRelax {
  double omega;
  template <class V>
  [[gnu::always_inline]] void operator()(V (&ev)[kPairs + 1], V (&od)[kPairs + 1]) const {
    kernel::scale_halves(ev, od, omega, omega);
  }
};

template <class Real>
[[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void sweep_bgk(const SweepRange<Real>& r, const BgkRelax& relax) {
  kernel::sweep(r, relax);
}

}  // namespace

std::unique_ptr<CollisionOperator> make_bgk(const CollisionParameters& p) {
  check_collision_parameters(p);
  return std::make_unique<kernel::OperatorFrom<BgkRelax>>("bgk", BgkRelax{1.0 / p.tau}, &sweep_bgk<double>,
                                                          &sweep_bgk<float>);
}

}  // namespace cmp::lbm
