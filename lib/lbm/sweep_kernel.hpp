#pragma once
// The fused stream-collide hot loop (internal to lib/lbm). Each collision style's .cpp
// instantiates it with its own relaxation functor, so the relaxation is inlined into the loop
// and the only virtual call is one per node range.
//
// A relaxation functor R has `template <int B> void operator()(double (&g)[kQ][B]) const`,
// replacing the non-equilibrium parts g of B nodes by R g (linear, see lbm/collision.hpp).
//
// Nodes go in batches of kBatch: gather 19 populations per node into a local array, collide
// there (vectorised across the batch), scatter back. No branches inside a batch and no
// divisions anywhere: the AA parity and the forcing are template parameters.
#include "lbm/collision.hpp"
#include "lbm/d3q19.hpp"

#include <cstdint>

namespace cmp::lbm::kernel {

inline constexpr int kBatch = 8;

// Equilibrium, Guo forcing and relaxation of B nodes in place: f[q][b] -> post-collision.
// force: 3 components (kForce) or unused.
template <int B, bool kForce, class Relax>
[[gnu::always_inline]] inline void collide_batch(double (&f)[kQ][B], const double* force, const Relax& relax) {
  double rho[B], ux[B], uy[B], uz[B];
  for (int b = 0; b < B; ++b) {
    double r = 0, x = 0, y = 0, z = 0;
    for (int q = 0; q < kQ; ++q) {
      r += f[q][b];
      x += kCx[q] * f[q][b];
      y += kCy[q] * f[q][b];
      z += kCz[q] * f[q][b];
    }
    rho[b] = r;
    ux[b] = x;
    uy[b] = y;
    uz[b] = z;
  }
  double gx = 0, gy = 0, gz = 0;
  if constexpr (kForce) {
    gx = force[0];
    gy = force[1];
    gz = force[2];
    for (int b = 0; b < B; ++b) {
      ux[b] += 0.5 * gx;
      uy[b] += 0.5 * gy;
      uz[b] += 0.5 * gz;
    }
  }
  double g[kQ][B];
  for (int q = 0; q < kQ; ++q) {
    const double w = weight(q);
    for (int b = 0; b < B; ++b) {
      const double cu = kCx[q] * ux[b] + kCy[q] * uy[b] + kCz[q] * uz[b];
      const double uu = ux[b] * ux[b] + uy[b] * uy[b] + uz[b] * uz[b];
      const double feq = w * (rho[b] + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
      g[q][b] = f[q][b] - feq;
      if constexpr (kForce) {
        const double cg = kCx[q] * gx + kCy[q] * gy + kCz[q] * gz;
        const double ug = ux[b] * gx + uy[b] * gy + uz[b] * gz;
        const double s = w * (3.0 * cg + 9.0 * cu * cg - 3.0 * ug);
        g[q][b] += 0.5 * s;
        f[q][b] += s;
      }
    }
  }
  relax(g);
  for (int q = 0; q < kQ; ++q)
    for (int b = 0; b < B; ++b) f[q][b] -= g[q][b];
}

// One AA step over [r.begin, r.end).
template <class Real, bool kOdd, bool kForce, class Relax>
[[gnu::always_inline]] inline void sweep_batches(const SweepRange<Real>& r, const Relax& relax) {
  constexpr int B = kBatch;
  Real* __restrict F = r.f;
  const std::uint32_t* __restrict L = r.links;
  const long N = r.stride;
  for (long base = r.begin; base < r.end; base += B) {
    double f[kQ][B];
    if constexpr (!kOdd) {
      for (int q = 0; q < kQ; ++q)
        for (int b = 0; b < B; ++b) f[q][b] = F[q * N + base + b];
    } else {
      for (int b = 0; b < B; ++b) f[0][b] = F[base + b];
      for (int q = 1; q < kQ; ++q)
        for (int b = 0; b < B; ++b) f[q][b] = F[L[(opposite(q) - 1) * N + base + b]];
    }
    collide_batch<B, kForce>(f, r.force, relax);
    if constexpr (!kOdd) {
      for (int q = 0; q < kQ; ++q)
        for (int b = 0; b < B; ++b) F[opposite(q) * N + base + b] = static_cast<Real>(f[q][b]);
    } else {
      for (int b = 0; b < B; ++b) F[base + b] = static_cast<Real>(f[0][b]);
      for (int q = 1; q < kQ; ++q)
        for (int b = 0; b < B; ++b) F[L[(q - 1) * N + base + b]] = static_cast<Real>(f[q][b]);
    }
  }
}

// Dispatch on parity and forcing.
template <class Real, class Relax>
[[gnu::always_inline]] inline void sweep(const SweepRange<Real>& r, const Relax& relax) {
  if (r.odd) {
    if (r.force) sweep_batches<Real, true, true>(r, relax);
    else sweep_batches<Real, true, false>(r, relax);
  } else {
    if (r.force) sweep_batches<Real, false, true>(r, relax);
    else sweep_batches<Real, false, false>(r, relax);
  }
}

// One node (for the tests' collide()).
template <class Relax>
inline void collide_one(double f[kQ], const double* force, const Relax& relax) {
  double batch[kQ][1];
  for (int q = 0; q < kQ; ++q) batch[q][0] = f[q];
  if (force) collide_batch<1, true>(batch, force, relax);
  else collide_batch<1, false>(batch, force, relax);
  for (int q = 0; q < kQ; ++q) f[q] = batch[q][0];
}

template <class Relax>
inline void relax_one(double g[kQ], const Relax& relax) {
  double batch[kQ][1];
  for (int q = 0; q < kQ; ++q) batch[q][0] = g[q];
  relax(batch);
  for (int q = 0; q < kQ; ++q) g[q] = batch[q][0];
}

// A CollisionOperator from a relaxation functor; the style files define
//   [[gnu::target_clones("avx2", "default")]] void sweep_<style>(const SweepRange<Real>&, const Relax&)
// so the hot loop gets an AVX2 clone, and wrap it in this class.
template <class Relax>
class OperatorFrom : public CollisionOperator {
 public:
  using SweepD = void (*)(const SweepRange<double>&, const Relax&);
  using SweepF = void (*)(const SweepRange<float>&, const Relax&);
  OperatorFrom(const char* name, const Relax& relax, SweepD sd, SweepF sf) : name_(name), relax_(relax), sd_(sd), sf_(sf) {}
  const char* name() const override { return name_; }
  void relax(double g[kQ]) const override { relax_one(g, relax_); }
  void collide(double f[kQ], const double* force) const override { collide_one(f, force, relax_); }
  void sweep(const SweepRange<double>& r) const override { sd_(r, relax_); }
  void sweep(const SweepRange<float>& r) const override { sf_(r, relax_); }

 private:
  const char* name_;
  Relax relax_;
  SweepD sd_;
  SweepF sf_;
};

}  // namespace cmp::lbm::kernel
