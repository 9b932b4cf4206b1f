#include "shell/svk_membrane.hpp"

#include "shell/rest_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::shell {

namespace {

// The columns one pass reads and writes.
struct SvkArrays {
  const double* x;                         // state
  const int *q0, *q1, *q2;                 // corners
  const double *L0, *L1, *L2;              // rest squared lengths of the edges opposite the corners
  const double *k0, *k1, *k2, *c0, *c1, *c2;
};

SvkArrays arrays(const ElementAssembly& a, const std::vector<double>& l2, const std::vector<double>& k,
                 const std::vector<double>& c, const double* x) {
  const long n = a.element_count();
  return {x, a.corner(0), a.corner(1), a.corner(2), l2.data(), l2.data() + n, l2.data() + 2 * n,
          k.data(), k.data() + n, k.data() + 2 * n, c.data(), c.data() + n, c.data() + 2 * n};
}

// Edge vectors e_i = (corner i+2) - (corner i+1) and d_i = |e_i|^2 - L_i^2 of triangle t.
struct Strains {
  double e[3][3], d[3];
};

[[gnu::always_inline]] inline Strains strains(const SvkArrays& A, long t) {
  const long i0 = 3L * A.q0[t], i1 = 3L * A.q1[t], i2 = 3L * A.q2[t];
  Strains s;
  for (int r = 0; r < 3; ++r) {
    const double p0 = A.x[i0 + r], p1 = A.x[i1 + r], p2 = A.x[i2 + r];
    s.e[0][r] = p2 - p1;
    s.e[1][r] = p0 - p2;
    s.e[2][r] = p1 - p0;
  }
  const double L[3] = {A.L0[t], A.L1[t], A.L2[t]};
  for (int i = 0; i < 3; ++i) s.d[i] = s.e[i][0] * s.e[i][0] + s.e[i][1] * s.e[i][1] + s.e[i][2] * s.e[i][2] - L[i];
  return s;
}

// The force pass on one tile (element_assembly.hpp): each lane does exactly the operations of
// strains() and the scalar formula in the same order, so the same bits as one triangle at a time.
[[gnu::always_inline]] inline void svk_tile(const SvkArrays& A, long t0, const double* __restrict P,
                                            double* __restrict O, int m) {
  const double *L0 = A.L0 + t0, *L1 = A.L1 + t0, *L2 = A.L2 + t0;
  const double *k0 = A.k0 + t0, *k1 = A.k1 + t0, *k2 = A.k2 + t0;
  const double *c0 = A.c0 + t0, *c1 = A.c1 + t0, *c2 = A.c2 + t0;
  for (int l = 0; l < m; ++l) {
    const auto p = [&](int row) { return P[row * kTile + l]; };
    // Edge vectors e_i = (corner i+2) - (corner i+1).
    const double e0x = p(6) - p(3), e0y = p(7) - p(4), e0z = p(8) - p(5);
    const double e1x = p(0) - p(6), e1y = p(1) - p(7), e1z = p(2) - p(8);
    const double e2x = p(3) - p(0), e2y = p(4) - p(1), e2z = p(5) - p(2);
    const double d0 = e0x * e0x + e0y * e0y + e0z * e0z - L0[l];
    const double d1 = e1x * e1x + e1y * e1y + e1z * e1z - L1[l];
    const double d2 = e2x * e2x + e2y * e2y + e2z * e2z - L2[l];
    // dE/d(l_i^2), times 2 for d(l_i^2)/d(end) = 2 e_i.
    const double w0 = k0[l] * d0 + c2[l] * d1 + c1[l] * d2;
    const double w1 = k1[l] * d1 + c2[l] * d0 + c0[l] * d2;
    const double w2 = k2[l] * d2 + c1[l] * d0 + c0[l] * d1;
    // Edge i runs from corner i+1 to corner i+2: +w_i e_i on its head, -w_i e_i on its tail.
    O[0 * kTile + l] = w1 * e1x - w2 * e2x;
    O[1 * kTile + l] = w1 * e1y - w2 * e2y;
    O[2 * kTile + l] = w1 * e1z - w2 * e2z;
    O[3 * kTile + l] = w2 * e2x - w0 * e0x;
    O[4 * kTile + l] = w2 * e2y - w0 * e0y;
    O[5 * kTile + l] = w2 * e2z - w0 * e0z;
    O[6 * kTile + l] = w0 * e0x - w1 * e1x;
    O[7 * kTile + l] = w0 * e0y - w1 * e1y;
    O[8 * kTile + l] = w0 * e0z - w1 * e1z;
  }
}

[[gnu::target_clones("avx2", "default")]] void svk_forces(const SvkArrays A, const CornerForces& out, long begin,
                                                          long end) {
  const CornerForces F = out;  // a local copy: the stores below cannot change it
  const int* corners[3] = {A.q0, A.q1, A.q2};
  alignas(64) double P[9 * kTile], O[9 * kTile];
  for (long t0 = begin; t0 < end; t0 += kTile) {
    const int m = static_cast<int>(std::min<long>(kTile, end - t0));
    load_tile<3>(A.x, corners, t0, m, P);
    svk_tile(A, t0, P, O, m);
    store_tile<3>(O, F, t0, m);
  }
}

double svk_energy(const SvkArrays& A, long begin, long end) {
  double sum = 0;
  for (long t = begin; t < end; ++t) {
    const Strains s = strains(A, t);
    const double* d = s.d;
    sum += 0.25 * (A.k0[t] * d[0] * d[0] + A.k1[t] * d[1] * d[1] + A.k2[t] * d[2] * d[2]) +
           0.5 * (A.c0[t] * d[1] * d[2] + A.c1[t] * d[2] * d[0] + A.c2[t] * d[0] * d[1]);
  }
  return sum;
}

}  // namespace

SvkMembrane::SvkMembrane(const mesh::TriMesh& rest, const MaterialParameters& p) : vertex_count_(rest.V.rows()) {
  validate(p, "svk");
  check_rest_mesh(rest, "svk");
  const Eigen::Index nf = rest.F.rows();
  std::vector<int> corners(3 * nf);
  rest_l2_.resize(3 * nf);
  k_.resize(3 * nf);
  c_.resize(3 * nf);
  const double Y = p.stretching_modulus(), nu = p.poisson_ratio;
  for (Eigen::Index f = 0; f < nf; ++f) {
    Eigen::Vector3d P[3];
    for (int i = 0; i < 3; ++i) {
      corners[3 * f + i] = rest.F(f, i);
      P[i] = rest.V.row(rest.F(f, i)).transpose();
    }
    const double A = 0.5 * (P[1] - P[0]).cross(P[2] - P[0]).norm();
    double cot[3];
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d u = P[(i + 1) % 3] - P[i], v = P[(i + 2) % 3] - P[i];
      cot[i] = u.dot(v) / u.cross(v).norm();  // cot of the rest angle at corner i
      rest_l2_[i * nf + f] = (P[(i + 2) % 3] - P[(i + 1) % 3]).squaredNorm();
    }
    const double scale = Y / (16.0 * (1.0 - nu * nu) * A);
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      k_[i * nf + f] = scale * (2.0 * cot[i] * cot[i] + 1.0 - nu);
      c_[i * nf + f] = scale * (2.0 * cot[a] * cot[b] + nu - 1.0);
    }
  }
  assembly_ = ElementAssembly(corners, 3, vertex_count_);
}

double SvkMembrane::energy(std::span<const double> x) const {
  check_sizes(x);
  const SvkArrays A = arrays(assembly_, rest_l2_, k_, c_, x.data());
  return assembly_.sum([&](long begin, long end) { return svk_energy(A, begin, end); });
}

void SvkMembrane::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const SvkArrays A = arrays(assembly_, rest_l2_, k_, c_, x.data());
  const CornerForces F = assembly_.corner_forces();
  assembly_.assemble([&](long begin, long end) { svk_forces(A, F, begin, end); }, g.data());
}

}  // namespace cmp::shell
