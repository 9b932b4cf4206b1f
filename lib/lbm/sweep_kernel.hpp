#pragma once
// The fused stream-collide hot loop (internal to lib/lbm). Each collision style's .cpp
// instantiates it with its own relaxation functor, so the relaxation is inlined into the loop
// and the only virtual call is one per node range.
//
// A relaxation functor R has `template <class V> void operator()(V (&ev)[kPairs + 1],
// V (&od)[kPairs + 1]) const`, replacing the non-equilibrium part g of one node (V = double) or
// of a block's kBatch nodes (V = Lanes) by R g (linear, see lbm/collision.hpp), g given by its
// halves over the pairs of opposite directions: ev[0] = g_0, ev[p] = (g_p + g_p+9)/2 and
// od[p] = (g_p - g_p+9)/2 for p = 1..9 (od[0] is zero and not read back); R must be
// straight-line code.
//
// Nodes go in blocks of kBatch. Double storage on an x86-64-v4 (AVX-512) processor: the
// collision works on the block's 19 lines as 19 vectors (sweep_v4). Otherwise (float storage,
// older processors): gather 19 populations per node into a local array, collide there
// (vectorised across the batch), scatter back. No branches inside a block and no divisions
// anywhere: the AA parity and the forcing are template parameters. Both paths do the same
// operations in the same order and the build contracts no multiply-add (-ffp-contract=off),
// so they give the same bits (tests/lbm/test_collision_styles.cpp checks the sweep against
// the one-node collision).
#include "lbm/collision.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/layout.hpp"

#include <immintrin.h>

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace cmp::lbm::kernel {

// One direction of a block's kBatch nodes, one node per lane (a GCC vector: arithmetic is
// element by element, so the code of one node runs unchanged on it).
typedef double Lanes __attribute__((vector_size(kBatch * sizeof(double))));

// Equilibrium, Guo forcing and relaxation of one node in place: f -> post-collision. Every
// loop over directions is unrolled, so the velocities and weights are constants. V is double
// (one node) or Lanes (a block's kBatch nodes, one per vector lane: the same operations in the
// same order, so the same bits). The work is done on the 9 pairs of opposite directions: the
// equilibrium of p and of p + 9 share their symmetric part and differ in the sign of the odd
// one, so the non-equilibrium's halves ev = (g_p + g_p+9)/2 and od = (g_p - g_p+9)/2 (what the
// relaxation works on) come from the pair's sum and difference directly (written direction by
// direction, the equilibrium, the split and the recombination took 40 % more floating-point
// operations; the odd step, which cannot hide them behind memory, spent a third of its time
// here). f_again, when given, holds f unchanged in memory (f[q] at f_again + q * lanes, lanes =
// 1 for double, kBatch for Lanes, any alignment): f is read from it again after the relaxation
// instead of being kept in registers through it (the forced collision holds f, g, s and the
// relaxation's temporaries, more than AVX-512's 32 registers, and spilled; reading the
// block's own lines again, still in L1, took the dense box's even steps from 155 to 207 MLUPS
// on two threads. Without forcing it cost 10-15 % on two threads, and on odd steps an explicit
// copy to the stack cost 7 %, so only forced even steps use it).
template <bool kForce, class V, class Relax>
[[gnu::always_inline]] inline void collide_node(V (&f)[kQ], double gx, double gy, double gz, const Relax& relax,
                                                const double* f_again = nullptr) {
  V sum[kPairs + 1], diff[kPairs + 1];
#pragma GCC unroll 9
  for (int p = 1; p <= kPairs; ++p) {
    sum[p] = f[p] + f[p + kPairs];
    diff[p] = f[p] - f[p + kPairs];
  }
  V rho = f[0], ux{}, uy{}, uz{};
#pragma GCC unroll 9
  for (int p = 1; p <= kPairs; ++p) {
    rho += sum[p];
    if (kCx[p] != 0) ux += double(kCx[p]) * diff[p];
    if (kCy[p] != 0) uy += double(kCy[p]) * diff[p];
    if (kCz[p] != 0) uz += double(kCz[p]) * diff[p];
  }
  if constexpr (kForce) {
    ux += 0.5 * gx;
    uy += 0.5 * gy;
    uz += 0.5 * gz;
  }
  const V rest = rho - 1.5 * (ux * ux + uy * uy + uz * uz);  // rho - 3/2 u.u
  V ev[kPairs + 1], od[kPairs + 1], se[kPairs + 1];
  double so[kPairs + 1] = {};  // the source's odd half: 3 w c.g, the same for every node
  ev[0] = f[0] - weight(0) * rest;
  od[0] = V{};
  V ug{};
  if constexpr (kForce) {
    ug = ux * gx + uy * gy + uz * gz;
    se[0] = weight(0) * (-3.0 * ug);
    ev[0] += 0.5 * se[0];
  }
#pragma GCC unroll 9
  for (int p = 1; p <= kPairs; ++p) {
    const double w = weight(p);
    V cu{};
    if (kCx[p] != 0) cu += double(kCx[p]) * ux;
    if (kCy[p] != 0) cu += double(kCy[p]) * uy;
    if (kCz[p] != 0) cu += double(kCz[p]) * uz;
    ev[p] = 0.5 * sum[p] - w * (rest + 4.5 * cu * cu);
    od[p] = 0.5 * diff[p] - (3 * w) * cu;
    if constexpr (kForce) {
      const double cg = kCx[p] * gx + kCy[p] * gy + kCz[p] * gz;
      se[p] = w * (9.0 * cu * cg - 3.0 * ug);
      so[p] = (3 * w) * cg;
      ev[p] += 0.5 * se[p];
      od[p] += 0.5 * so[p];
    }
  }
  relax(ev, od);
  if (f_again) {
    asm volatile("" ::: "memory");  // so the compiler reads f_again here, not keeps the first read
#pragma GCC unroll 19
    for (int q = 0; q < kQ; ++q) std::memcpy(&f[q], f_again + q * (sizeof(V) / sizeof(double)), sizeof(V));
  }
  f[0] -= ev[0];
  if constexpr (kForce) f[0] += se[0];
#pragma GCC unroll 9
  for (int p = 1; p <= kPairs; ++p) {
    f[p] -= ev[p] + od[p];
    f[p + kPairs] -= ev[p] - od[p];
    if constexpr (kForce) {
      f[p] += se[p] + so[p];
      f[p + kPairs] += se[p] - so[p];
    }
  }
}

// BGK's and TRT's relaxation: the symmetric half scaled by s_even, the antisymmetric one by
// s_odd.
template <class V>
[[gnu::always_inline]] inline void scale_halves(V (&ev)[kPairs + 1], V (&od)[kPairs + 1], double s_even, double s_odd) {
  ev[0] *= s_even;
#pragma GCC unroll 9
  for (int p = 1; p <= kPairs; ++p) {
    ev[p] *= s_even;
    od[p] *= s_odd;
  }
}

// The same on a batch f[q][b], vectorised across the batch.
template <int B, bool kForce, class Relax>
[[gnu::always_inline]] inline void collide_batch(double (&f)[kQ][B], const double* force, const Relax& relax) {
  double gx = 0, gy = 0, gz = 0;
  if constexpr (kForce) {
    gx = force[0];
    gy = force[1];
    gz = force[2];
  }
#pragma omp simd
  for (int b = 0; b < B; ++b) {
    double node[kQ];
#pragma GCC unroll 19
    for (int q = 0; q < kQ; ++q) node[q] = f[q][b];
    collide_node<kForce>(node, gx, gy, gz, relax);
#pragma GCC unroll 19
    for (int q = 0; q < kQ; ++q) f[q][b] = node[q];
  }
}

// A stored value to f_q and back (lbm/layout.hpp: float slots hold f_q - w_q; q is a constant
// in every unrolled loop, so double storage costs nothing).
template <class Real>
[[gnu::always_inline]] inline double widen(Real v, int q) {
  if constexpr (std::is_same_v<Real, float>) return static_cast<double>(v) + stored_offset<Real>(q);
  else return v;
}
template <class Real>
[[gnu::always_inline]] inline Real narrow(double f, int q) {
  if constexpr (std::is_same_v<Real, float>) return static_cast<Real>(f - stored_offset<Real>(q));
  else return f;
}

// One direction's line of a block (kBatch values) to f_q and back; float converts 4 lanes at a
// time (left to itself the compiler converted lane by lane).
typedef float Float4 __attribute__((vector_size(16)));
typedef double Double4 __attribute__((vector_size(32)));
template <class Real>
[[gnu::always_inline]] inline void widen_line(const Real* src, int q, double* dst) {
  if constexpr (std::is_same_v<Real, float>) {
    for (int h = 0; h < kBatch; h += 4) {
      Float4 x;
      std::memcpy(&x, src + h, sizeof x);
      const Double4 y = __builtin_convertvector(x, Double4) + stored_offset<Real>(q);
      std::memcpy(dst + h, &y, sizeof y);
    }
  } else {
    for (int b = 0; b < kBatch; ++b) dst[b] = src[b];
  }
}
template <class Real>
[[gnu::always_inline]] inline void narrow_line(const double* src, int q, Real* dst) {
  if constexpr (std::is_same_v<Real, float>) {
    for (int h = 0; h < kBatch; h += 4) {
      Double4 x;
      std::memcpy(&x, src + h, sizeof x);
      const Float4 y = __builtin_convertvector(x - stored_offset<Real>(q), Float4);
      std::memcpy(dst + h, &y, sizeof y);
    }
  } else {
    for (int b = 0; b < kBatch; ++b) dst[b] = src[b];
  }
}

// Blocks ahead whose neighbour lines an odd step prefetches.
inline constexpr int kPrefetchAhead = 4;

// One AA step over [r.begin, r.end).
template <class Real, bool kOdd, bool kForce, class Relax>
[[gnu::always_inline]] inline void sweep_batches(const SweepRange<Real>& r, const Relax& relax) {
  constexpr int B = kBatch;
  Real* __restrict F = r.f;
  const std::uint32_t* __restrict L = r.links;
  const bool every_slot = r.consecutive == nullptr;
  for (long base = r.begin; base < r.end; base += B) {
    Real* __restrict own = F + kQ * base;                     // this block's populations
    const std::uint32_t* __restrict link = L + (kQ - 1) * base;  // this block's links
    double f[kQ][B];
    if constexpr (!kOdd) {
      for (int q = 0; q < kQ; ++q) widen_line(own + B * q, q, f[q]);
    } else {
      // The neighbours' lines of a batch a few blocks ahead (the hardware prefetchers do not
      // follow the link table; the table has kPrefetchAhead blocks of padding at its end):
      // the slot of lane 0 in chunks of mostly consecutive lines, every slot elsewhere, as
      // sweep_blocks_v4 does (float storage, odd steps on two threads: porous box 49 -> 59
      // MLUPS; the dense box lost 7 % with every slot).
      const std::uint32_t* ahead = link + (kQ - 1) * kPrefetchAhead * B;
      if (every_slot) {
        for (int q = 1; q < kQ; ++q)
          for (int b = 0; b < B; ++b) __builtin_prefetch(F + ahead[B * (q - 1) + b], 1);
      } else {
        for (int q = 1; q < kQ; ++q) __builtin_prefetch(F + ahead[B * (q - 1)], 1);
      }
      for (int b = 0; b < B; ++b) f[0][b] = widen<Real>(own[b], 0);
      for (int q = 1; q < kQ; ++q)
        for (int b = 0; b < B; ++b) f[q][b] = widen<Real>(F[link[B * (opposite(q) - 1) + b]], q);
    }
    collide_batch<B, kForce>(f, r.force, relax);
    if constexpr (!kOdd) {
      for (int q = 0; q < kQ; ++q) narrow_line(f[q], q, own + B * opposite(q));
    } else {
      for (int b = 0; b < B; ++b) own[b] = narrow<Real>(f[0][b], 0);
      for (int q = 1; q < kQ; ++q)
        for (int b = 0; b < B; ++b) F[link[B * (q - 1) + b]] = narrow<Real>(f[q][b], q);
    }
  }
}

// A block line of 8 doubles to 8 slots, element by element: on Zen 5 faster than one AVX-512
// scatter (bench_lbm, odd steps on two threads: porous box 48-50 -> 53-57 MLUPS with
// element-wise loads as well; dense box, whose scattered lines are runs across two blocks,
// 88 -> 98). The loads stay gathers: once every slot is prefetched (below), the gather beats
// element-wise loads (porous 73 -> 78).
[[gnu::target("arch=x86-64-v4"), gnu::always_inline]] inline void store_line(double* F, const std::uint32_t* s, Lanes v) {
#pragma GCC unroll 8
  for (int b = 0; b < kBatch; ++b) F[s[b]] = v[b];
}

// One AA step over [r.begin, r.end) in double precision with AVX-512 (x86-64-v4): the
// collision works on a block's 19 lines as 19 vectors (one node per lane), loaded and stored
// in place by the even steps, gathered from the neighbours' slots through the link table by
// the odd steps and stored back element by element (store_line), except, in the chunks where
// r.consecutive is set, the lines it marks, which are loaded and stored as one vector (on
// bench_lbm's dense 128^3 box, 8 of 18 lines, that took one thread's odd steps from ~45 to
// ~51 MLUPS; its porous box, 6.5 % of lines, lost ~10 % to the branch, so the solver passes
// r.consecutive only where such lines are common). Same operations in the
// same order as sweep_batches, so the same bits.
template <bool kOdd, bool kForce, bool kConsecutive, class Relax>
[[gnu::target("arch=x86-64-v4"), gnu::always_inline]] inline void sweep_blocks_v4(const SweepRange<double>& r,
                                                                                  const Relax& relax) {
  static_assert(kBatch == 8, "one block line is one AVX-512 vector");
  double* __restrict F = r.f;
  const std::uint32_t* __restrict L = r.links;
  double gx = 0, gy = 0, gz = 0;
  if constexpr (kForce) {
    gx = r.force[0];
    gy = r.force[1];
    gz = r.force[2];
  }
  for (long base = r.begin; base < r.end; base += kBatch) {
    double* own = F + kQ * base;
    const std::uint32_t* link = L + (kQ - 1) * base;
    const std::uint32_t consecutive = kConsecutive ? r.consecutive[base / kBatch] : 0;
    Lanes f[kQ];
    if constexpr (!kOdd) {
#pragma GCC unroll 19
      for (int q = 0; q < kQ; ++q) f[q] = _mm512_loadu_pd(own + kBatch * q);
      // All 19 loads first, in order: left to itself the compiler spread them through the
      // collision, and the memory-bound even steps lost 10-20 % (porous 128^3 box, two threads).
#pragma GCC unroll 19
      for (int q = 0; q < kQ; ++q) asm volatile("" : "+v"(f[q]));
    } else {
      // The neighbours' slots of the block kPrefetchAhead blocks ahead: where lines are mostly
      // consecutive, the slot of lane 0 (its cache line holds most of the line); elsewhere every
      // slot, since a scattered line touches up to 8 cache lines (bench_lbm's porous box, odd
      // steps on two threads: 60 -> 77 MLUPS, one thread 33 -> 44; lanes 0, 2, 4, 6, 7: 72;
      // lanes 0 and 7: 67; every slot 3 or 6 blocks ahead: 67; on the dense box every slot
      // cost 18 %).
      const std::uint32_t* ahead = link + (kQ - 1) * kPrefetchAhead * kBatch;
      if constexpr (kConsecutive) {
#pragma GCC unroll 18
        for (int q = 1; q < kQ; ++q) __builtin_prefetch(F + ahead[kBatch * (q - 1)], 1);
      } else {
#pragma GCC unroll 18
        for (int q = 1; q < kQ; ++q)
#pragma GCC unroll 8
          for (int b = 0; b < kBatch; ++b) __builtin_prefetch(F + ahead[kBatch * (q - 1) + b], 1);
      }
      f[0] = _mm512_loadu_pd(own);
#pragma GCC unroll 18
      for (int q = 1; q < kQ; ++q) {
        const std::uint32_t* slots = link + kBatch * (opposite(q) - 1);
        if (kConsecutive && (consecutive >> opposite(q) & 1)) f[q] = _mm512_loadu_pd(F + slots[0]);
        else f[q] = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(slots)), F, 8);
      }
    }
    if constexpr (!kOdd && kForce) collide_node<kForce>(f, gx, gy, gz, relax, own);
    else collide_node<kForce>(f, gx, gy, gz, relax);
    if constexpr (!kOdd) {
#pragma GCC unroll 19
      for (int q = 0; q < kQ; ++q) _mm512_storeu_pd(own + kBatch * opposite(q), f[q]);
    } else {
      _mm512_storeu_pd(own, f[0]);
#pragma GCC unroll 18
      for (int q = 1; q < kQ; ++q) {
        const std::uint32_t* slots = link + kBatch * (q - 1);
        if (kConsecutive && (consecutive >> q & 1)) _mm512_storeu_pd(F + slots[0], f[q]);
        else store_line(F, slots, f[q]);
      }
    }
  }
}

template <class Relax>
[[gnu::target("arch=x86-64-v4")]] void sweep_v4(const SweepRange<double>& r, const Relax& relax) {
  if (r.odd && r.consecutive) {
    if (r.force) sweep_blocks_v4<true, true, true>(r, relax);
    else sweep_blocks_v4<true, false, true>(r, relax);
  } else if (r.odd) {
    if (r.force) sweep_blocks_v4<true, true, false>(r, relax);
    else sweep_blocks_v4<true, false, false>(r, relax);
  } else {
    if (r.force) sweep_blocks_v4<false, true, false>(r, relax);
    else sweep_blocks_v4<false, false, false>(r, relax);
  }
}

// Whether this processor runs sweep_v4.
inline bool has_v4() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("x86-64-v4") != 0;
  }();
  return yes;
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
  double ev[kPairs + 1], od[kPairs + 1];
  ev[0] = g[0];
  od[0] = 0;
  for (int p = 1; p <= kPairs; ++p) {
    ev[p] = 0.5 * (g[p] + g[p + kPairs]);
    od[p] = 0.5 * (g[p] - g[p + kPairs]);
  }
  relax(ev, od);
  g[0] = ev[0];
  for (int p = 1; p <= kPairs; ++p) {
    g[p] = ev[p] + od[p];
    g[p + kPairs] = ev[p] - od[p];
  }
}

// A CollisionOperator from a relaxation functor; the style files define
//   [[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void sweep_<style>(const SweepRange<Real>&, const Relax&)
// so the batch loop gets an AVX-512 clone and an AVX2 one, picked when the program loads; on
// an x86-64-v4 processor double storage runs sweep_v4 instead (on a Zen 5 core it took MRT's
// even steps from ~60 to ~77 MLUPS, odd steps from ~34 to ~41). Results are the same for any
// thread count and any of these paths. Wrap it in this class.
template <class Relax>
class OperatorFrom : public CollisionOperator {
 public:
  using SweepD = void (*)(const SweepRange<double>&, const Relax&);
  using SweepF = void (*)(const SweepRange<float>&, const Relax&);
  OperatorFrom(const char* name, const Relax& relax, SweepD sd, SweepF sf)
      : name_(name), relax_(relax), sd_(has_v4() ? &sweep_v4<Relax> : sd), sf_(sf) {}
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
