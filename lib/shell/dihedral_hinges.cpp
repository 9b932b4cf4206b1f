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

// The hinge's geometry: e = x1 - x0, the face normals N0 = e x (x2 - x0) and
// N1 = (x3 - x0) x e (unnormalised, |N| = 2 area), and phi.
struct Hinge {
  double e[3], N0[3], N1[3], phi;
};

inline Hinge hinge(const double* x0, const double* x1, const double* x2, const double* x3) {
  Hinge h;
  double a[3], b[3], m[3];
  sub(x1, x0, h.e);
  sub(x2, x0, a);
  sub(x3, x0, b);
  cross(h.e, a, h.N0);
  cross(b, h.e, h.N1);
  cross(h.N0, h.N1, m);
  // sin(phi) |N0||N1| = (N0 x N1) . e/|e|, cos(phi) |N0||N1| = N0 . N1.
  h.phi = std::atan2(dot(m, h.e) / std::sqrt(dot(h.e, h.e)), dot(h.N0, h.N1));
  return h;
}

}  // namespace

double hinge_angle(const double* x0, const double* x1, const double* x2, const double* x3) {
  return hinge(x0, x1, x2, x3).phi;
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
    const Hinge h = hinge(X + 3 * i, X + 3 * j, X + 3 * k, X + 3 * l);
    const double area = 0.5 * (std::sqrt(dot(h.N0, h.N0)) + std::sqrt(dot(h.N1, h.N1)));
    quad_.insert(quad_.end(), {i, j, k, l});
    phi0_.push_back(h.phi);
    kappa_.push_back(stiffness == HingeStiffness::Local ? 3.0 * dot(h.e, h.e) * kappa / area
                                                        : 2.0 * kappa / std::sqrt(3.0));
  }
}

double DihedralHinges::energy(std::span<const double> x) const {
  check_sizes(x);
  const double* X = x.data();
  const std::size_t nh = phi0_.size();
  double sum = 0;
  for (std::size_t h = 0; h < nh; ++h) {
    const int* q = &quad_[4 * h];
    const double phi = hinge(X + 3 * q[0], X + 3 * q[1], X + 3 * q[2], X + 3 * q[3]).phi;
    sum += kappa_[h] * (1.0 - std::cos(phi - phi0_[h]));
  }
  return sum;
}

void DihedralHinges::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const double* X = x.data();
  double* G = g.data();
  const std::size_t nh = phi0_.size();
  for (std::size_t h = 0; h < nh; ++h) {
    const int* q = &quad_[4 * h];
    const double *x0 = X + 3 * q[0], *x2 = X + 3 * q[2], *x3 = X + 3 * q[3];
    const Hinge H = hinge(x0, X + 3 * q[1], x2, x3);
    const double s = kappa_[h] * std::sin(H.phi - phi0_[h]);  // dE/dphi
    const double e2 = dot(H.e, H.e), le = std::sqrt(e2);
    const double n0 = dot(H.N0, H.N0), n1 = dot(H.N1, H.N1);
    double a[3], b[3];
    sub(x2, x0, a);
    sub(x3, x0, b);
    const double t2 = dot(a, H.e) / e2, t3 = dot(b, H.e) / e2;  // the wings' positions along e
    double g2[3], g3[3];
    for (int r = 0; r < 3; ++r) {
      g2[r] = -le / n0 * H.N0[r];  // dphi/dx2 = -|e| N0/|N0|^2 = -|e|/(2 A0) n0
      g3[r] = -le / n1 * H.N1[r];
    }
    double* G0 = G + 3 * q[0];
    double* G1 = G + 3 * q[1];
    double* G2 = G + 3 * q[2];
    double* G3 = G + 3 * q[3];
    for (int r = 0; r < 3; ++r) {
      G2[r] += s * g2[r];
      G3[r] += s * g3[r];
      G0[r] -= s * ((1.0 - t2) * g2[r] + (1.0 - t3) * g3[r]);
      G1[r] -= s * (t2 * g2[r] + t3 * g3[r]);
    }
  }
}

}  // namespace cmp::shell
