#include "elasticity/buckling.hpp"

#include "mesh/disc_mesh.hpp"
#include "mesh/edge_topology.hpp"
#include "mesh/face_normals.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace cmp::elasticity;

namespace {
// Energy per area, in units of kappa~/Rc^2, of normal-vector hinges sum (1 - n_a . n_b) on a flat
// hexagonal disc (R = 10, a = 0.35) whose vertices are mapped by `map` onto a surface with
// curvatures of order 1/Rc, counting the hinges within r < 6 of the centre.
double hinge_energy_density(const std::function<Eigen::Vector3d(double, double)>& map, double Rc) {
  static const auto d = cmp::mesh::disc_mesh(10.0, 3000);
  cmp::mesh::VertexMatrix V = d.mesh.V;
  for (Eigen::Index i = 0; i < V.rows(); ++i) V.row(i) = map(d.mesh.V(i, 0), d.mesh.V(i, 1)).transpose();
  const auto N = cmp::mesh::face_normals(V, d.mesh.F);
  const auto topo = cmp::mesh::edge_topology(d.mesh.F);
  double E = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    if (topo.edge_face_counts[static_cast<std::size_t>(e)] != 2) continue;
    const Eigen::Vector3d mid = 0.5 * (d.mesh.V.row(topo.edges(e, 0)) + d.mesh.V.row(topo.edges(e, 1)));
    if (mid.head<2>().norm() > 6.0) continue;
    E += 1 - N.row(topo.edge_faces(e, 0)).dot(N.row(topo.edge_faces(e, 1)));
  }
  return E / (M_PI * 36) * Rc * Rc;
}
}  // namespace

TEST_CASE("normal-vector hinges bend like (sqrt(3)/2) kappa~ with a Gaussian modulus -(2/sqrt(3)) kappa~",
          "[elasticity][calibration]") {
  const double Rc = 40, kt = 1.0;
  const double kappa = hinge_bending_rigidity(kt, HingeCalibration::Cylinder), kG = hinge_gaussian_modulus(kt);
  // Cylinders with the lattice rows across and along the axis: (kappa/2)/Rc^2.
  const double across = hinge_energy_density([&](double x, double y) {
    return Eigen::Vector3d(Rc * std::sin(x / Rc), y, Rc * (1 - std::cos(x / Rc)));
  }, Rc);
  const double along = hinge_energy_density([&](double x, double y) {
    return Eigen::Vector3d(x, Rc * std::sin(y / Rc), Rc * (1 - std::cos(y / Rc)));
  }, Rc);
  CHECK(across == Approx(kappa / 2).epsilon(0.01));
  CHECK(along == Approx(kappa / 2).epsilon(0.01));
  // Sphere: (kappa/2)(2/Rc)^2 + kG/Rc^2; saddle z = (x^2 - y^2)/(2 Rc): -kG/Rc^2.
  const double sphere = hinge_energy_density([&](double x, double y) {
    const double r = std::hypot(x, y), s = r > 0 ? Rc * std::sin(r / Rc) / r : 1.0;
    return Eigen::Vector3d(x * s, y * s, Rc * (1 - std::cos(r / Rc)));
  }, Rc);
  const double saddle = hinge_energy_density([&](double x, double y) {
    return Eigen::Vector3d(x, y, (x * x - y * y) / (2 * Rc));
  }, Rc);
  CHECK(sphere == Approx(2 * kappa + kG).epsilon(0.01));
  // (the graph's curvatures fall by |grad z|^2 ~ 2 % towards r = 6: a looser tolerance)
  CHECK(saddle == Approx(-kG).epsilon(0.025));
  // A closed sphere's total 4 pi (2 kappa + kG) is 8 pi times the Sphere calibration.
  CHECK(4 * M_PI * (2 * kappa + kG) == Approx(8 * M_PI * hinge_bending_rigidity(kt, HingeCalibration::Sphere)).epsilon(1e-12));
}
