// TRT (two relaxation times, Ginzburg): the symmetric part of the non-equilibrium relaxes at
// s+ = 1/tau (viscosity), the antisymmetric part at s- chosen so that the magic parameter
// Lambda = (1/s+ - 1/2)(1/s- - 1/2) is fixed (3/16 by default): the steady solution, and so
// the permeability, is then the same for every tau.
#include "lbm/collision_styles.hpp"
#include "lbm/sweep_kernel.hpp"

namespace cmp::lbm {

namespace {

struct TrtRelax {
  double plus, minus;  // s+, s-
  template <class V>
  [[gnu::always_inline]] void operator()(V (&ev)[kPairs + 1], V (&od)[kPairs + 1]) const {
    kernel::scale_halves(ev, od, plus, minus);
  }
};

template <class Real>
[[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void sweep_trt(const SweepRange<Real>& r, const TrtRelax& relax) {
  kernel::sweep(r, relax);
}

}  // namespace

double odd_rate(const CollisionParameters& p) { return 1.0 / (p.magic / (p.tau - 0.5) + 0.5); }

std::unique_ptr<CollisionOperator> make_trt(const CollisionParameters& p) {
  check_collision_parameters(p);
  return std::make_unique<kernel::OperatorFrom<TrtRelax>>("trt", TrtRelax{1.0 / p.tau, odd_rate(p)},
                                                          &sweep_trt<double>, &sweep_trt<float>);
}

}  // namespace cmp::lbm
