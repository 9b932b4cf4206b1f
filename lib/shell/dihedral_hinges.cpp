#include "shell/dihedral_hinges.hpp"

#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"
#include "mesh/edge_topology.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp::shell {

namespace {

inline void sub(const double* a, const double* b, double* r) { r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2]; }
inline void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1], r[1] = a[2] * b[0] - a[0] * b[2], r[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// cos phi and sin phi of the hinge (x0, x1, x2, x3), with its geometry: e = x1 - x0,
// a = x2 - x0, b = x3 - x0, the face normals N0 = e x a and N1 = b x e (unnormalised,
// |N| = 2 area), n0 = |N0|^2, n1 = |N1|^2, e2 = |e|^2, le = |e|.
// sin(phi) |N0||N1| = (N0 x N1) . e/|e|, cos(phi) |N0||N1| = N0 . N1.
struct HingeAngle {
  double e[3], a[3], b[3], N0[3], N1[3], n0, n1, e2, le, inv_e2, inv_n01, c, s;
};

[[gnu::always_inline]] inline HingeAngle hinge_cos_sin(const double* x0, const double* x1, const double* x2,
                                                       const double* x3) {
  HingeAngle h;
  sub(x1, x0, h.e);
  sub(x2, x0, h.a);
  sub(x3, x0, h.b);
  cross(h.e, h.a, h.N0);
  cross(h.b, h.e, h.N1);
  double m[3];
  cross(h.N0, h.N1, m);
  h.n0 = dot(h.N0, h.N0), h.n1 = dot(h.N1, h.N1), h.e2 = dot(h.e, h.e);
  // Two divisions and two square roots in all (the force pass's critical path).
  h.inv_e2 = 1.0 / h.e2;
  h.inv_n01 = 1.0 / (h.n0 * h.n1);
  h.le = std::sqrt(h.e2);
  const double r = std::sqrt(h.inv_n01);  // 1/(|N0||N1|)
  h.c = dot(h.N0, h.N1) * r;
  h.s = dot(m, h.e) * (h.le * h.inv_e2) * r;  // |e|/|e|^2 = 1/|e|
  return h;
}

// The columns one pass reads and writes.
struct HingeArrays {
  const double* x;
  const int *q0, *q1, *q2, *q3;
  const double *kappa, *cos0, *sin0;
};

// 1 - cos(phi - phi0) from cos(phi - phi0) and sin(phi - phi0), without cancellation near 0.
[[gnu::always_inline]] inline double one_minus_cos(double cd, double sd) {
  return cd > 0 ? sd * sd / (1.0 + cd) : 1.0 - cd;
}

// The force pass on one tile (element_assembly.hpp): each lane does exactly the operations of
// hinge_cos_sin in the same order.
[[gnu::always_inline]] inline void hinge_tile(const double* __restrict P, double* __restrict O,
                                              const double* __restrict kappa, const double* __restrict cos0,
                                              const double* __restrict sin0, int m) {
  for (int l = 0; l < m; ++l) {
    const auto p = [&](int row) { return P[row * kTile + l]; };
    const double ex = p(3) - p(0), ey = p(4) - p(1), ez = p(5) - p(2);
    const double ax = p(6) - p(0), ay = p(7) - p(1), az = p(8) - p(2);
    const double bx = p(9) - p(0), by = p(10) - p(1), bz = p(11) - p(2);
    const double n0x = ey * az - ez * ay, n0y = ez * ax - ex * az, n0z = ex * ay - ey * ax;
    const double n1x = by * ez - bz * ey, n1y = bz * ex - bx * ez, n1z = bx * ey - by * ex;
    const double mx = n0y * n1z - n0z * n1y, my = n0z * n1x - n0x * n1z, mz = n0x * n1y - n0y * n1x;
    const double n0 = n0x * n0x + n0y * n0y + n0z * n0z, n1 = n1x * n1x + n1y * n1y + n1z * n1z;
    const double e2 = ex * ex + ey * ey + ez * ez;
    const double inv_e2 = 1.0 / e2, inv_n01 = 1.0 / (n0 * n1);
    const double le = std::sqrt(e2), r = std::sqrt(inv_n01);
    const double c = (n0x * n1x + n0y * n1y + n0z * n1z) * r;
    const double sn = (mx * ex + my * ey + mz * ez) * (le * inv_e2) * r;
    const double s = kappa[l] * (sn * cos0[l] - c * sin0[l]);  // dE/dphi = kappa sin(phi - phi0)
    const double t2 = (ax * ex + ay * ey + az * ez) * inv_e2, t3 = (bx * ex + by * ey + bz * ez) * inv_e2;
    // dphi/dx2 = -|e| N0/|N0|^2 = -|e|/(2 A0) n0, and likewise on x3 (1/n0 = n1/(n0 n1)).
    const double sl = -s * le * inv_n01, s2 = sl * n1, s3 = sl * n0;
    const double g2[3] = {s2 * n0x, s2 * n0y, s2 * n0z}, g3[3] = {s3 * n1x, s3 * n1y, s3 * n1z};
    for (int q = 0; q < 3; ++q) {
      O[q * kTile + l] = -((1.0 - t2) * g2[q] + (1.0 - t3) * g3[q]);
      O[(3 + q) * kTile + l] = -(t2 * g2[q] + t3 * g3[q]);
      O[(6 + q) * kTile + l] = g2[q];
      O[(9 + q) * kTile + l] = g3[q];
    }
  }
}

[[gnu::target_clones("avx2", "default")]] void hinge_forces(const HingeArrays A, const CornerForces& out, long begin,
                                                            long end) {
  const CornerForces F = out;  // a local copy: the stores below cannot change it
  const int* corners[4] = {A.q0, A.q1, A.q2, A.q3};
  alignas(64) double P[12 * kTile], O[12 * kTile];
  for (long t0 = begin; t0 < end; t0 += kTile) {
    const int m = static_cast<int>(std::min<long>(kTile, end - t0));
    load_tile<4>(A.x, corners, t0, m, P);
    hinge_tile(P, O, A.kappa + t0, A.cos0 + t0, A.sin0 + t0, m);
    store_tile<4>(O, F, t0, m);
  }
}

double hinge_energy(const HingeArrays& A, long begin, long end) {
  double sum = 0;
  for (long h = begin; h < end; ++h) {
    const HingeAngle H = hinge_cos_sin(A.x + 3 * A.q0[h], A.x + 3 * A.q1[h], A.x + 3 * A.q2[h], A.x + 3 * A.q3[h]);
    const double cd = H.c * A.cos0[h] + H.s * A.sin0[h], sd = H.s * A.cos0[h] - H.c * A.sin0[h];
    sum += A.kappa[h] * one_minus_cos(cd, sd);
  }
  return sum;
}

}  // namespace

double hinge_angle(const double* x0, const double* x1, const double* x2, const double* x3) {
  const HingeAngle h = hinge_cos_sin(x0, x1, x2, x3);
  return std::atan2(h.s, h.c);
}

DihedralHinges::DihedralHinges(const mesh::TriMesh& rest, const MaterialParameters& p, HingeStiffness stiffness,
                               std::string name)
    : name_(std::move(name)), vertex_count_(rest.V.rows()) {
  validate(p, name_.c_str());
  check_rest_mesh(rest, name_.c_str());
  const double kappa = p.bending_rigidity();
  const auto topo = mesh::edge_topology(rest.F);
  const double* X = rest.V.data();
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    if (topo.edge_face_counts[e] != 2) continue;
    int i = topo.edges(e, 0), j = topo.edges(e, 1);
    int f0 = topo.edge_faces(e, 0), f1 = topo.edge_faces(e, 1);
    if (!mesh::face_has_side(rest.F, f0, i, j)) std::swap(f0, f1);
    if (!mesh::face_has_side(rest.F, f0, i, j) || !mesh::face_has_side(rest.F, f1, j, i)) {
      // f0 may run j -> i: take the edge the other way round.
      std::swap(i, j);
      if (!mesh::face_has_side(rest.F, f0, i, j)) std::swap(f0, f1);
      if (!mesh::face_has_side(rest.F, f0, i, j) || !mesh::face_has_side(rest.F, f1, j, i))
        throw UsageError(name_ + ": the faces " + std::to_string(topo.edge_faces(e, 0)) + " and " +
                         std::to_string(topo.edge_faces(e, 1)) + " on edge " + std::to_string(topo.edges(e, 0)) +
                         "-" + std::to_string(topo.edges(e, 1)) + " are oriented inconsistently");
    }
    auto third = [&](int f) {
      for (int c = 0; c < 3; ++c)
        if (rest.F(f, c) != i && rest.F(f, c) != j) return rest.F(f, c);
      return -1;
    };
    const int k = third(f0), l = third(f1);
    const HingeAngle h = hinge_cos_sin(X + 3 * i, X + 3 * j, X + 3 * k, X + 3 * l);
    const double area = 0.5 * (std::sqrt(h.n0) + std::sqrt(h.n1));
    quad_.insert(quad_.end(), {i, j, k, l});
    phi0_.push_back(std::atan2(h.s, h.c));
    cos0_.push_back(h.c);
    sin0_.push_back(h.s);
    kappa_.push_back(stiffness == HingeStiffness::Local ? 3.0 * h.e2 * kappa / area
                                                        : 2.0 * kappa / std::sqrt(3.0));
  }
  assembly_ = ElementAssembly(quad_, 4, vertex_count_);
}

double DihedralHinges::energy(std::span<const double> x) const {
  check_sizes(x);
  const HingeArrays A{x.data(), assembly_.corner(0), assembly_.corner(1), assembly_.corner(2), assembly_.corner(3),
                      kappa_.data(), cos0_.data(), sin0_.data()};
  return assembly_.sum([&](long begin, long end) { return hinge_energy(A, begin, end); });
}

void DihedralHinges::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const HingeArrays A{x.data(), assembly_.corner(0), assembly_.corner(1), assembly_.corner(2), assembly_.corner(3),
                      kappa_.data(), cos0_.data(), sin0_.data()};
  const CornerForces F = assembly_.corner_forces();
  assembly_.assemble([&](long begin, long end) { hinge_forces(A, F, begin, end); }, g.data());
}

}  // namespace cmp::shell
