#include "shell/edge_springs.hpp"

#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"
#include "mesh/edge_topology.hpp"

#include <cmath>

namespace cmp::shell {

namespace {
Eigen::Vector3d vertex(const mesh::TriMesh& m, int i) { return m.V.row(i).transpose(); }

// The columns one pass reads and writes.
struct EdgeArrays {
  const double* x;
  const int *q0, *q1;
  const double *rest, *k;
};

void spring_forces(const EdgeArrays A, const CornerForces& out, long begin, long end) {
  const CornerForces F = out;  // a local copy: the stores below cannot change it
  for (long e = begin; e < end; ++e) {
    const double* a = A.x + 3 * A.q0[e];
    const double* b = A.x + 3 * A.q1[e];
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double s = A.k[e] * (1.0 - A.rest[e] / l);  // dE/dl / l
    double *f0 = F.at(0, e), *f1 = F.at(1, e);
    for (int r = 0; r < 3; ++r) {
      f0[r] = -s * d[r];
      f1[r] = s * d[r];
    }
  }
}

double spring_energy(const EdgeArrays& A, long begin, long end) {
  double sum = 0;
  for (long e = begin; e < end; ++e) {
    const double* a = A.x + 3 * A.q0[e];
    const double* b = A.x + 3 * A.q1[e];
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - A.rest[e];
    sum += 0.5 * A.k[e] * stretch * stretch;
  }
  return sum;
}
}  // namespace

std::vector<double> edge_spring_constants(const mesh::TriMesh& rest, const MaterialParameters& p,
                                          SpringConstants rule) {
  const auto topo = mesh::edge_topology(rest.F);
  const Eigen::Index ne = topo.edges.rows();
  const double Y = p.stretching_modulus(), nu = p.poisson_ratio;
  std::vector<double> k(ne, 0.0);
  switch (rule) {
    case SpringConstants::SeungNelson:
      for (auto& v : k) v = std::sqrt(3.0) * Y / 2.0;
      break;
    case SpringConstants::Kot: {
      double area = 0, sum_l2 = 0;
      for (Eigen::Index f = 0; f < rest.F.rows(); ++f) {
        const auto a = vertex(rest, rest.F(f, 0)), b = vertex(rest, rest.F(f, 1)), c = vertex(rest, rest.F(f, 2));
        area += 0.5 * (b - a).cross(c - a).norm();
      }
      for (Eigen::Index e = 0; e < ne; ++e)
        sum_l2 += (vertex(rest, topo.edges(e, 1)) - vertex(rest, topo.edges(e, 0))).squaredNorm();
      for (auto& v : k) v = 2.0 * Y / (1.0 - nu) * area / sum_l2;
      break;
    }
    case SpringConstants::VanGelder:
      for (Eigen::Index e = 0; e < ne; ++e) {
        const int i = topo.edges(e, 0), j = topo.edges(e, 1);
        for (int side = 0; side < 2; ++side) {
          const int f = topo.edge_faces(e, side);
          if (f < 0) continue;
          int o = -1;  // the corner of f opposite edge e
          for (int c = 0; c < 3; ++c)
            if (rest.F(f, c) != i && rest.F(f, c) != j) o = rest.F(f, c);
          const auto pi = vertex(rest, i), pj = vertex(rest, j), po = vertex(rest, o);
          const double c2 = (pj - pi).squaredNorm(), a2 = (po - pj).squaredNorm(), b2 = (po - pi).squaredNorm();
          const double A = 0.5 * (pj - pi).cross(po - pi).norm();
          k[e] += Y / (1.0 + nu) * A / c2 + Y * nu / (1.0 - nu * nu) * (a2 + b2 - c2) / (8.0 * A);
        }
      }
      break;
  }
  return k;
}

EdgeSprings::EdgeSprings(const mesh::TriMesh& rest, const MaterialParameters& p, SpringConstants rule,
                         std::string name)
    : name_(std::move(name)), vertex_count_(rest.V.rows()) {
  validate(p, name_.c_str());
  check_rest_mesh(rest, name_.c_str());
  const auto topo = mesh::edge_topology(rest.F);
  const Eigen::Index ne = topo.edges.rows();
  ends_.resize(2 * ne);
  rest_.resize(ne);
  for (Eigen::Index e = 0; e < ne; ++e) {
    ends_[2 * e] = topo.edges(e, 0);
    ends_[2 * e + 1] = topo.edges(e, 1);
    rest_[e] = (vertex(rest, topo.edges(e, 1)) - vertex(rest, topo.edges(e, 0))).norm();
  }
  k_ = edge_spring_constants(rest, p, rule);
  for (Eigen::Index e = 0; e < ne; ++e)
    if (!(k_[e] > 0))
      throw UsageError(name_ + ": edge " + std::to_string(ends_[2 * e]) + "-" + std::to_string(ends_[2 * e + 1]) +
                       " gets a spring constant that is not positive (an obtuse rest triangle with nu > 0?)");
  assembly_ = ElementAssembly(ends_, 2, vertex_count_);
}

double EdgeSprings::energy(std::span<const double> x) const {
  check_sizes(x);
  const EdgeArrays A{x.data(), assembly_.corner(0), assembly_.corner(1), rest_.data(), k_.data()};
  return assembly_.sum([&](long begin, long end) { return spring_energy(A, begin, end); });
}

void EdgeSprings::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const EdgeArrays A{x.data(), assembly_.corner(0), assembly_.corner(1), rest_.data(), k_.data()};
  const CornerForces F = assembly_.corner_forces();
  assembly_.assemble([&](long begin, long end) { spring_forces(A, F, begin, end); }, g.data());
}

}  // namespace cmp::shell
