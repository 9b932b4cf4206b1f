// The structure observables of shell packings (shellpack analyze): inter-shell contacts and
// forces (Eqs. S4.1-S4.5), shapes (Eq. 4.6), wall load (Fig. 4.5b), periodic Voronoi facets.
#include "packing_fixtures.hpp"

#include "mesh/face_areas.hpp"
#include "shell/hertz_contacts.hpp"
#include "shell/shell_contact_forces.hpp"
#include "shell/shell_shapes.hpp"
#include "shell/voronoi_faces.hpp"
#include "shell/wall_load.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp;
using namespace cmp::shell;

namespace {

// Two level-3 icospheres (162 vertices) of radius 1 facing each other vertex to vertex along
// x (B is A mirrored in the plane x = c), their tips overlapping by `overlap`.
fixtures::SyntheticPacking two_touching_spheres(double rv, double overlap) {
  const auto a = fixtures::icosphere_vertex_on_x(3, 1.0);
  mesh::TriMesh b = a;
  const double c = 1.0 + rv - 0.5 * overlap;
  for (Eigen::Index i = 0; i < b.V.rows(); ++i) b.V(i, 0) = 2 * c - b.V(i, 0);
  b.F.col(1).swap(b.F.col(2));  // the mirror turns the faces inward: turn them back
  fixtures::SyntheticPacking p;
  fixtures::add_shell(p, a, Eigen::Vector3d(3, 3, 3));
  fixtures::add_shell(p, b, Eigen::Vector3d(3, 3, 3));
  return p;
}

neighbours::Box box_of(double side, bool periodic) {
  neighbours::Box b;
  b.lengths = Eigen::Vector3d::Constant(side);
  b.periodic = {periodic, periodic, periodic};
  return b;
}

}  // namespace

TEST_CASE("shell contacts: two spheres pressed together push along their centre line, Newton's third law",
          "[packing_observables]") {
  ContactParameters cp;
  cp.vertex_radius = 0.1;
  cp.youngs_modulus = 3.0;
  cp.poisson_ratio = 0.5;
  const auto p = two_touching_spheres(cp.vertex_radius, 0.05);
  for (const bool periodic : {false, true}) {
    const auto contacts = shell_contacts(p.V, p.F, p.offsets, box_of(12.0, periodic), cp);
    REQUIRE(contacts.size() == 2);  // (0, 1) and (1, 0)
    CHECK(contacts_per_shell(contacts, 2) == std::vector<int>{1, 1});
    const auto& c01 = contacts[0];
    const auto& c10 = contacts[1];
    CHECK(c01.m == 0);
    CHECK(c01.n == 1);
    CHECK(c01.image == Eigen::Vector3i::Zero());
    CHECK(c01.vertex_pairs == c10.vertex_pairs);
    // The force on A (at smaller x) from B, summed by hand over every overlapping pair.
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    int pairs = 0;
    for (int i = p.offsets[0]; i < p.offsets[1]; ++i)
      for (int j = p.offsets[1]; j < p.offsets[2]; ++j) {
        const Eigen::Vector3d d = (p.V.row(i) - p.V.row(j)).transpose();
        const double r = d.norm();
        if (r >= 2 * cp.vertex_radius) continue;
        ++pairs;
        expected += cmp::hertz_force(cmp::hertz_prefactor(cp.vertex_effective_modulus(), 0.5 * cp.vertex_radius), 2 * cp.vertex_radius - r) / r * d;
      }
    CHECK(c01.vertex_pairs == pairs);
    CHECK(pairs >= 1);
    CHECK(expected.x() < 0);
    CHECK((c01.force - expected).norm() <= 1e-12 * expected.norm());
    CHECK((c01.force + c10.force).norm() <= 1e-12 * expected.norm());  // F_mn = -F_nm
    CHECK(std::abs(c01.force.y()) + std::abs(c01.force.z()) <= 1e-12 * expected.norm());  // along the centre line
    // Head-on: the normal part carries almost all of it (the tangential rest is the tilt of
    // the faces around the overlapping vertices, about 1 - cos 10 deg).
    CHECK(c01.normal.norm() == Approx(expected.norm()).epsilon(0.05));
    CHECK(c01.tangential.norm() < 0.05 * c01.normal.norm());
    CHECK(c01.normal.dot(expected) > 0);
    CHECK(effective_friction(contacts) < 0.05);
    CHECK(effective_friction(contacts) == Approx(c01.tangential.norm() / c01.normal.norm()).epsilon(1e-9).margin(0));
  }
}

TEST_CASE("shell contacts: Eq. S4.5 on two icosahedra tip to tip, normal part |F| cos of the face tilt",
          "[packing_observables]") {
  // Only the two tip vertices overlap. The five faces around a tip are tilted from the tip
  // direction by the same angle, cos = inradius / circumradius = sqrt((5 + 2 sqrt 5) / 15),
  // so S4.5 gives |F| cos along F, and mu_eff = (1 - cos) / cos.
  ContactParameters cp;
  cp.vertex_radius = 0.1;
  const double overlap = 0.05;
  const auto a = fixtures::icosphere_vertex_on_x(1, 1.0);  // the icosahedron itself
  mesh::TriMesh b = a;
  const double c = 1.0 + cp.vertex_radius - 0.5 * overlap;
  for (Eigen::Index i = 0; i < b.V.rows(); ++i) b.V(i, 0) = 2 * c - b.V(i, 0);
  b.F.col(1).swap(b.F.col(2));
  fixtures::SyntheticPacking p;
  fixtures::add_shell(p, a, Eigen::Vector3d::Zero());
  fixtures::add_shell(p, b, Eigen::Vector3d::Zero());
  const auto contacts = shell_contacts(p.V, p.F, p.offsets, box_of(10.0, false), cp);
  REQUIRE(contacts.size() == 2);
  CHECK(contacts[0].vertex_pairs == 1);
  const double f = cmp::hertz_force(cmp::hertz_prefactor(cp.vertex_effective_modulus(), 0.5 * cp.vertex_radius), overlap);
  const double cosine = std::sqrt((5 + 2 * std::sqrt(5.0)) / 15);
  CHECK((contacts[0].force - Eigen::Vector3d(-f, 0, 0)).norm() <= 1e-12 * f);
  CHECK((contacts[0].normal - Eigen::Vector3d(-f * cosine, 0, 0)).norm() <= 1e-12 * f);
  CHECK((contacts[0].tangential - Eigen::Vector3d(-f * (1 - cosine), 0, 0)).norm() <= 1e-12 * f);
  CHECK(effective_friction(contacts) == Approx((1 - cosine) / cosine).epsilon(1e-12));
}

TEST_CASE("shell contacts: apart by more than 2 R_v no contact, a sheared pair has a tangential part",
          "[packing_observables]") {
  ContactParameters cp;
  cp.vertex_radius = 0.1;
  auto p = two_touching_spheres(cp.vertex_radius, -0.01);  // tips 2 R_v + 0.01 apart
  CHECK(shell_contacts(p.V, p.F, p.offsets, box_of(12.0, false), cp).empty());
  // Shift B sideways: the force tilts off the centre line and the S4.5 normal part (along
  // the face normals) no longer carries all of it.
  p = two_touching_spheres(cp.vertex_radius, 0.15);
  for (int i = p.offsets[1]; i < p.offsets[2]; ++i) p.V(i, 1) += 0.1;
  const auto contacts = shell_contacts(p.V, p.F, p.offsets, box_of(12.0, false), cp);
  REQUIRE(contacts.size() == 2);
  CHECK((contacts[0].force + contacts[1].force).norm() <= 1e-12 * contacts[0].force.norm());
  CHECK(contacts[0].tangential.norm() > 0);
  CHECK(effective_friction(contacts) > 0);
}

TEST_CASE("shell contacts: across a periodic face, by the minimum image, with the image named", "[packing_observables]") {
  ContactParameters cp;
  cp.vertex_radius = 0.1;
  auto p = two_touching_spheres(cp.vertex_radius, 0.05);
  // Move B by one box side along x: only the minimum image brings it back.
  const double side = 8.0;
  for (int i = p.offsets[1]; i < p.offsets[2]; ++i) p.V(i, 0) += side;
  CHECK(shell_contacts(p.V, p.F, p.offsets, box_of(side, false), cp).empty());
  const auto contacts = shell_contacts(p.V, p.F, p.offsets, box_of(side, true), cp);
  REQUIRE(contacts.size() == 2);
  CHECK(contacts[0].image == Eigen::Vector3i(-1, 0, 0));  // B's image one side back along x
  CHECK(contacts[1].image == Eigen::Vector3i(1, 0, 0));
  CHECK(contacts[0].force.x() < 0);
}

TEST_CASE("shell shapes: a stretched icosphere has the gyration of its vertex cloud", "[packing_observables]") {
  // The level-3 icosphere has icosahedral symmetry, so its vertices' second moment is I/3;
  // stretched by (a, b, c) it is diag(a^2, b^2, c^2)/3.
  auto m = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, 3, 1.0);
  const double a = 1.3, b = 1.0, c = 0.8;
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) m.V.row(i) = m.V.row(i).cwiseProduct(Eigen::RowVector3d(a, b, c));
  fixtures::SyntheticPacking p;
  fixtures::add_shell(p, spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, 2, 1.0), {0, 0, 0});
  fixtures::add_shell(p, m, {5, 6, 7});
  const auto shapes = shell_shapes(p.V, p.offsets);
  REQUIRE(shapes.size() == 2);
  CHECK(shapes[0].asphericity == Approx(0).margin(1e-14));
  CHECK(shapes[0].aspect_deviation == Approx(0).margin(1e-14));
  CHECK((shapes[1].centre - Eigen::Vector3d(5, 6, 7)).norm() < 1e-13);
  CHECK(shapes[1].gyration[0] == Approx(a * a / 3).epsilon(1e-12));
  CHECK(shapes[1].gyration[1] == Approx(b * b / 3).epsilon(1e-12));
  CHECK(shapes[1].gyration[2] == Approx(c * c / 3).epsilon(1e-12));
  CHECK(shapes[1].asphericity == Approx((a * a - 0.5 * (b * b + c * c)) / 3).epsilon(1e-12));
  CHECK(shapes[1].aspect_deviation == Approx(a / c - 1).epsilon(1e-12));
}

TEST_CASE("wall load: pressure and coverage of a shell flattened against a wall, by hand", "[packing_observables]") {
  // A level-3 sphere of radius 1 whose vertices below z = z0 + h are pressed flat onto the
  // plane z = z0 + h (a contact patch), with that plane R_v - overlap above the wall z = 0.
  ContactParameters cp;
  cp.vertex_radius = 0.05;
  cp.youngs_modulus = 2.0;
  cp.poisson_ratio = 0.5;
  const double overlap = 0.01, flat = -0.9;  // the patch: z < -0.9 of the unit sphere
  auto m = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, 3, 1.0);
  std::vector<char> in_patch(m.V.rows(), 0);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    if (m.V(i, 2) < flat) {
      m.V(i, 2) = flat;
      in_patch[i] = 1;
    }
  fixtures::SyntheticPacking p;
  const double lx = 4, ly = 5, lz = 6;
  fixtures::add_shell(p, m, Eigen::Vector3d(2, 2.5, cp.vertex_radius - overlap - flat));
  const Eigen::Vector3d box(lx, ly, lz);
  const WallLoad load = wall_load(p.V, p.F, box, {true, true, false}, cp);
  int touching = 0;
  for (char t : in_patch) touching += t;
  REQUIRE(touching >= 3);
  const double estar = 1.0 / ((1 - 0.25) / 2.0);  // rigid wall: E* = E / (1 - nu^2)
  const double force = touching * (4.0 / 3.0) * estar * std::sqrt(cp.vertex_radius) * std::pow(overlap, 1.5);
  const Eigen::VectorXd areas = mesh::face_areas(p.V, p.F);
  double patch = 0;
  for (Eigen::Index f = 0; f < p.F.rows(); ++f)
    if (in_patch[p.F(f, 0)] && in_patch[p.F(f, 1)] && in_patch[p.F(f, 2)]) patch += areas[f];
  REQUIRE(patch > 0);
  CHECK(load.walls == 2);
  CHECK(load.wall_area == Approx(2 * lx * ly));
  CHECK(load.force == Approx(force).epsilon(1e-12));
  CHECK(load.pressure() == Approx(force / (2 * lx * ly)).epsilon(1e-12));
  CHECK(load.coverage() == Approx(patch / (2 * lx * ly)).epsilon(1e-12));
  // Every axis periodic: no wall.
  CHECK(wall_load(p.V, p.F, box, {true, true, true}, cp).walls == 0);
}

TEST_CASE("periodic Voronoi cells: 6 facets on a simple cubic lattice, 12 on FCC, 14 on BCC", "[packing_observables]") {
  auto as_matrix = [](const std::vector<Eigen::Vector3d>& s) {
    mesh::VertexMatrix P(static_cast<Eigen::Index>(s.size()), 3);
    for (std::size_t i = 0; i < s.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = s[i].transpose();
    return P;
  };
  for (const int n : {1, 2, 3}) {  // one point alone and eight: CGAL's 27-sheeted cover
    const auto faces = periodic_voronoi_face_counts(as_matrix(fixtures::cubic_lattice(n, 1.0, false)), n);
    CHECK(faces == std::vector<int>(static_cast<std::size_t>(n * n * n), 6));
  }
  for (const int n : {1, 2}) {
    const auto faces = periodic_voronoi_face_counts(as_matrix(fixtures::cubic_lattice(n, 1.5, true)), 1.5 * n);
    CHECK(faces == std::vector<int>(static_cast<std::size_t>(4 * n * n * n), 12));
  }
  auto bcc = fixtures::cubic_lattice(2, 1.0, false);
  const auto sc = bcc;
  for (const auto& s : sc) bcc.push_back(s + Eigen::Vector3d::Constant(0.5));
  CHECK(periodic_voronoi_face_counts(as_matrix(bcc), 2.0) == std::vector<int>(16, 14));
  // Points outside the cube are wrapped into it.
  auto shifted = as_matrix(fixtures::cubic_lattice(2, 1.0, false));
  shifted.col(0).array() += 7.0;
  CHECK(periodic_voronoi_face_counts(shifted, 2.0) == std::vector<int>(8, 6));
}
