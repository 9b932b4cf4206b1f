#include "shell/dihedral_hinges.hpp"

#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"
#include "mesh/edge_topology.hpp"

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

void hinge_forces(const HingeArrays A, double* const* out, long begin,
                                                            long end) {
  double* F[4];  // local copies: the stores below cannot change them
  for (int k = 0; k < 4; ++k) F[k] = out[k];
  for (long h = begin; h < end; ++h) {
    const HingeAngle H = hinge_cos_sin(A.x + 3 * A.q0[h], A.x + 3 * A.q1[h], A.x + 3 * A.q2[h], A.x + 3 * A.q3[h]);
    const double s = A.kappa[h] * (H.s * A.cos0[h] - H.c * A.sin0[h]);  // dE/dphi = kappa sin(phi - phi0)
    const double t2 = dot(H.a, H.e) * H.inv_e2, t3 = dot(H.b, H.e) * H.inv_e2;  // the wings' positions along e
    // dphi/dx2 = -|e| N0/|N0|^2 = -|e|/(2 A0) n0, and likewise on x3 (1/n0 = n1/(n0 n1)).
    const double sl = -s * H.le * H.inv_n01, s2 = sl * H.n1, s3 = sl * H.n0;
    for (int r = 0; r < 3; ++r) {
      const double g2 = s2 * H.N0[r], g3 = s3 * H.N1[r];
      F[0][3 * h + r] = -((1.0 - t2) * g2 + (1.0 - t3) * g3);
      F[1][3 * h + r] = -(t2 * g2 + t3 * g3);
      F[2][3 * h + r] = g2;
      F[3][3 * h + r] = g3;
    }
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
  double* F[4];
  for (int k = 0; k < 4; ++k) F[k] = assembly_.corner_forces(k);
  assembly_.assemble([&](long begin, long end) { hinge_forces(A, F, begin, end); }, g.data());
}

}  // namespace cmp::shell
