#pragma once
// Collision operators are styles: one small interface (CollisionOperator), one file each
// (bgk.cpp, trt.cpp, mrt.cpp), one registry table (collision_styles()), from which a program
// builds `--collision NAME` and `--list-models`; tests/lbm/test_collision_styles.cpp checks
// every registered entry.
//
// Every style relaxes the non-equilibrium part of the populations around the same
// equilibrium, the incompressible (He & Luo 1997) second-order polynomial
//   f_q^eq = w_q [rho + 3 c_q.u + 9/2 (c_q.u)^2 - 3/2 u.u],  u = j / rho_0, rho_0 = 1,
// which is what the MRT moments of d'Humieres et al. (2002) reduce to with their equilibrium
// parameters w_eps = 3, w_epsj = -11/2, w_xx = -1/2. Kinematic viscosity nu = (tau - 1/2)/3.
// A body force g (Guo, Zheng & Shi 2002) enters as u = j + g/2 and a source term S_q; the
// styles only supply the linear relaxation R (f* = f + S - R(f - f^eq + S/2)), so the
// forcing is the same for all of them.
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace cmp::lbm {

struct CollisionParameters {
  double tau = 1.0;             // relaxation time of the shear stress moments, > 1/2; nu = (tau - 1/2)/3
  double magic = 3.0 / 16.0;    // TRT/MRT magic parameter Lambda = (1/s+ - 1/2)(1/s- - 1/2); 3/16 puts
                                // the bounce-back wall exactly half-way for Poiseuille flow, for every tau
};

// One contiguous range of nodes swept by one fused stream-collide step (lbm/flow_step.cpp).
template <class Real>
struct SweepRange {
  Real* f;                          // populations, laid out as lbm/layout.hpp says
  const std::uint32_t* links;       // the link table (slot indices into f), lbm/layout.hpp
  long begin, end;                  // node range, multiples of the kernel's batch size
  bool odd;                         // AA-pattern parity of this step
  const double* force;              // body force (3 values) or nullptr
  const std::uint32_t* consecutive = nullptr;  // per block (node / kBatch): consecutive_lines()
                                               // (lbm/layout.hpp), or nullptr: gather and scatter every line
};

class CollisionOperator {
 public:
  virtual ~CollisionOperator() = default;
  // The registered name.
  virtual const char* name() const = 0;
  // Relaxation of one node's non-equilibrium part, in place: g <- R g (R is linear and leaves
  // the mass and momentum moments of g untouched when they are zero). For tests.
  virtual void relax(double g[19]) const = 0;
  // Collision of one node in place (populations f, body force or nullptr); for tests.
  virtual void collide(double f[19], const double* force) const = 0;
  // The fused stream-collide sweep over one node range (the hot loop).
  virtual void sweep(const SweepRange<double>& range) const = 0;
  virtual void sweep(const SweepRange<float>& range) const = 0;
};

struct CollisionStyle {
  const char* name;         // as given on the command line, e.g. "mrt"
  const char* description;  // one line for --list-models
  // Builds the operator; throws cmp::UsageError for bad parameters (tau <= 1/2, magic <= 0).
  std::unique_ptr<CollisionOperator> (*make)(const CollisionParameters& p);
};

// The registered styles, default ("mrt") first.
std::span<const CollisionStyle> collision_styles();
// The entry called `name`; throws cmp::UsageError "unknown collision model 'x' (known: ...)".
const CollisionStyle& collision_style(const std::string& name);
// Checks tau > 1/2 and magic > 0; throws cmp::UsageError otherwise.
void check_collision_parameters(const CollisionParameters& p);

}  // namespace cmp::lbm
