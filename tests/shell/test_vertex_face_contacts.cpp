// hertz-faces (lib/shell/vertex_face_contacts.hpp): the closest point of a triangle region by
// region, the force of one vertex on one triangle (direction, magnitude, Newton's third law),
// the barrier over a whole coarse shell against vertex spheres of the same reach, periodic
// images, and the same bits on 1 and 2 threads. Gradients and invariances: the generic harness
// (tests/forcefield).
#include "shell/hertz_contacts.hpp"
#include "shell/vertex_face_contacts.hpp"
#include "shell/element_assembly.hpp"

#include "core/errors.hpp"
#include "spheremesh/subdivision.hpp"

#include "shell_fixtures.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

#include <array>
#include <cmath>
#include <vector>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;
using Eigen::Vector3d;

namespace {

// Two shells of one triangle each: A = (0,0,0), (1,0,0), (0,1,0) in the plane z = 0, and B a
// thin triangle whose first corner (vertex 3) is the probe p, its other corners 0.5 from p
// along `out` (away from A, so that no other corner comes within reach).
cmp::mesh::TriMesh probe_mesh(const Vector3d& p, const Vector3d& out = Vector3d::UnitZ()) {
  const Vector3d u = out.normalized(), far = p + 0.5 * u, side = far + 0.1 * u.unitOrthogonal();
  cmp::mesh::TriMesh m;
  m.V.resize(6, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, p.x(), p.y(), p.z(), far.x(), far.y(), far.z(), side.x(), side.y(), side.z();
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 3, 4, 5;
  return m;
}

ContactParameters parameters(double delta) {
  ContactParameters c;
  c.contact_distance = delta;
  c.vertex_radius = delta / 2;  // vertex spheres of the same reach: contact at 2 R_v = delta
  c.youngs_modulus = 2.0;
  c.poisson_ratio = 0.3;
  return c;
}

std::vector<double> gradient(const EnergyTerm& t, const std::vector<double>& x) {
  std::vector<double> g(x.size(), 0.0);
  t.add_gradient(x, g);
  return g;
}

// One probe at p against triangle A: the contact's distance, direction and weights, the force
// on p along p - closest with the Hertz magnitude, the triangle's corners taking the opposite
// by the weights, and the forces summing to zero. Over a corner, that corner is as close to
// p's own triangle (at p): a second, mirror contact doubles the force.
void check_probe(const Vector3d& p, const Vector3d& closest, const Vector3d& weights) {
  INFO("probe " << p.transpose());
  const double delta = 0.1;
  const auto mesh = probe_mesh(p, p - closest);
  const ContactParameters c = parameters(delta);
  const VertexFaceContacts term(mesh, c);
  const auto x = fx::state(mesh.V);
  const auto contacts = term.touches(x);
  const bool corner = weights.maxCoeff() == 1.0;
  REQUIRE(contacts.size() == (corner ? 2u : 1u));
  const auto& k = contacts.back();  // vertices in ascending order: the probe (3) comes last
  const double r = (p - closest).norm();
  CHECK(k.i == 3);
  CHECK(k.corners == std::array<int, 3>{0, 1, 2});  // triangle A
  CHECK(k.r == Approx(r).epsilon(1e-14));
  CHECK((k.d - (p - closest)).norm() < 1e-14);
  CHECK((k.weights - weights).norm() < 1e-14);
  if (corner) {
    CHECK(contacts[0].corners == std::array<int, 3>{3, 4, 5});  // A's corner against B at the probe
    CHECK(contacts[0].weights == Vector3d(1, 0, 0));
    CHECK((contacts[0].d + k.d).norm() < 1e-14);
  }
  const double h = delta - r, estar = c.vertex_effective_modulus();
  CHECK(k.overlap == Approx(h));
  CHECK(k.force == Approx(4.0 / 3.0 * estar * std::sqrt(delta / 2) * std::pow(h, 1.5)).epsilon(1e-13));
  const double u = 8.0 / 15.0 * estar * std::sqrt(delta / 2) * std::pow(h, 2.5);
  CHECK(term.energy(x) == Approx(corner ? 2 * u : u).epsilon(1e-13));
  const auto g = gradient(term, x);
  const Vector3d on_p = -Vector3d(g[9], g[10], g[11]);
  CHECK((on_p - (corner ? 2 : 1) * k.force * (p - closest) / r).norm() < 1e-12 * k.force);
  Vector3d total = on_p;
  for (int v = 0; v < 3; ++v) {
    const Vector3d on_v = -Vector3d(g[3 * v], g[3 * v + 1], g[3 * v + 2]);
    CHECK((on_v + weights[v] * on_p).norm() < 1e-12 * k.force);
    total += on_v;
  }
  CHECK(total.norm() < 1e-14 * k.force);
  for (int v = 4; v < 6; ++v) CHECK(Vector3d(g[3 * v], g[3 * v + 1], g[3 * v + 2]).norm() == 0.0);
  const auto t = term.touching(x);
  CHECK(t[3] == 1);
  for (int v = 0; v < 3; ++v) CHECK(t[v] == (weights[v] > 0 ? 1 : 0));
}

}  // namespace

TEST_CASE("closest point of a triangle: interior, edge and corner regions", "[shell][faces]") {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto near = [](const Vector3d& w, const Vector3d& want) { return (w - want).norm() < 1e-15; };
  CHECK(near(closest_triangle_weights({0.2, 0.3, 0.5}, a, b, c), {0.5, 0.2, 0.3}));    // above the interior
  CHECK(near(closest_triangle_weights({0.2, 0.3, -0.5}, a, b, c), {0.5, 0.2, 0.3}));   // below it
  CHECK(near(closest_triangle_weights({0.25, -0.3, 0.2}, a, b, c), {0.75, 0.25, 0}));  // edge ab
  CHECK(near(closest_triangle_weights({-0.4, 0.6, 0.1}, a, b, c), {0.4, 0, 0.6}));     // edge ca
  CHECK(near(closest_triangle_weights({0.8, 0.6, 0.3}, a, b, c), {0, 0.6, 0.4}));      // edge bc
  CHECK(near(closest_triangle_weights({-0.2, -0.1, 0.1}, a, b, c), {1, 0, 0}));        // corner a
  CHECK(near(closest_triangle_weights({1.3, -0.1, 0.0}, a, b, c), {0, 1, 0}));         // corner b
  CHECK(near(closest_triangle_weights({-0.1, 1.5, 2.0}, a, b, c), {0, 0, 1}));         // corner c
  CHECK(near(closest_triangle_weights({0.3, 0.3, 0.0}, a, b, c), {0.4, 0.3, 0.3}));    // in the plane
}

TEST_CASE("hertz-faces: one vertex over a triangle's interior, edge and corner", "[shell][faces]") {
  // Interior: along the normal.
  check_probe({0.2, 0.3, 0.05}, {0.2, 0.3, 0}, {0.5, 0.2, 0.3});
  // Edge ab: along the edge's outward normal in the plane of p and the edge.
  check_probe({0.5, -0.04, 0.03}, {0.5, 0, 0}, {0.5, 0.5, 0});
  // Hypotenuse bc, below the plane.
  check_probe({0.55, 0.55, -0.02}, {0.5, 0.5, 0}, {0, 0.5, 0.5});
  // Corner a: along p - a.
  check_probe({-0.04, -0.03, 0.05}, {0, 0, 0}, {1, 0, 0});
  // Out of reach: no contact, no energy.
  const auto far = probe_mesh({0.2, 0.3, 0.1001});
  const VertexFaceContacts term(far, parameters(0.1));
  CHECK(term.touches(fx::state(far.V)).empty());
  CHECK(term.energy(fx::state(far.V)) == 0.0);
}

TEST_CASE("hertz-faces: a barrier at every point of a coarse shell where vertex spheres of the same reach have holes",
          "[shell][faces]") {
  // Shell B: the 162-vertex icosphere of radius 1 (edges ~0.28, circumradii ~0.16). A probe
  // vertex crosses B's surface along the normal through every face centre and every edge
  // midpoint; the contact reach delta = 0.02 is far below the circumradius.
  const auto sphere = cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 3, 1.0);
  REQUIRE(sphere.V.rows() == 162);
  const double delta = 0.02;
  const ContactParameters c = parameters(delta);
  std::vector<Vector3d> targets;
  for (Eigen::Index f = 0; f < sphere.F.rows(); ++f) {
    const Vector3d a = sphere.V.row(sphere.F(f, 0)), b = sphere.V.row(sphere.F(f, 1)), cc = sphere.V.row(sphere.F(f, 2));
    targets.push_back((a + b + cc) / 3);
    targets.push_back((a + b) / 2);
  }
  const double barrier = 8.0 / 15.0 * c.vertex_effective_modulus() * std::sqrt(delta / 2) * std::pow(delta, 2.5);
  long faces_blocked = 0, spheres_blocked = 0;
  for (const Vector3d& s : targets) {
    // The probe shell: a thin triangle from the probe outward along the normal (short, so the
    // cutoff delta + longest edge stays near the mesh's own).
    const Vector3d n = s.normalized(), side = n.unitOrthogonal();
    cmp::mesh::TriMesh m;
    m.V.resize(165, 3);
    m.V.topRows(162) = sphere.V;
    m.V.row(162) = s.transpose();
    m.V.row(163) = (s + 0.25 * n).transpose();
    m.V.row(164) = (s + 0.25 * n + 0.05 * side).transpose();
    m.F.resize(sphere.F.rows() + 1, 3);
    m.F.topRows(sphere.F.rows()) = sphere.F;
    m.F.bottomRows(1) << 162, 163, 164;
    const VertexFaceContacts faces(m, c);
    const VertexContacts spheres(m, c);
    auto x = fx::state(m.V);
    // On the surface: faces hold the full barrier U(delta); vertex spheres none at all.
    const double ef = faces.energy(x), ev = spheres.energy(x);
    faces_blocked += ef >= barrier * (1 - 1e-9);
    spheres_blocked += ev > 0;
    // Just outside, the force on the probe points out of B; just inside, into it (the barrier
    // is the distance's, not a side's).
    for (double side_sign : {1.0, -1.0}) {
      const Vector3d p = s + side_sign * 0.005 * n;
      for (int a = 0; a < 3; ++a) x[3 * 162 + a] = p[a];
      const auto g = gradient(faces, x);
      CHECK(-side_sign * Vector3d(g[486], g[487], g[488]).dot(n) > 0);
    }
  }
  CHECK(faces_blocked == static_cast<long>(targets.size()));
  CHECK(spheres_blocked == 0);
}

TEST_CASE("hertz-faces: contacts through the periodic faces of the box", "[shell][faces]") {
  // The probe over triangle A's interior, then A moved by box vectors: the same contact
  // through the minimum image, none in open space.
  const double L = 8.0;
  const auto mesh = probe_mesh({0.2, 0.3, 0.05});
  ContactParameters c = parameters(0.1);
  VertexFaceContacts open(mesh, c);
  c.box = Vector3d(L, L, 12.0);
  c.box_periodic = {true, true, false};
  VertexFaceContacts periodic(mesh, c);
  auto x = fx::state(mesh.V);
  const double e = open.energy(x);
  REQUIRE(e > 0);
  for (int v = 0; v < 3; ++v) x[3 * v] -= L, x[3 * v + 1] += 2 * L;
  CHECK(open.energy(x) == 0.0);
  CHECK(periodic.energy(x) == Approx(e).epsilon(1e-12));
  const auto k = periodic.touches(x);
  REQUIRE(k.size() == 1);
  CHECK((k[0].d - Vector3d(0, 0, 0.05)).norm() < 1e-12);
  // Along the non-periodic z the image does not count.
  for (int v = 0; v < 3; ++v) x[3 * v + 2] += 12.0;
  CHECK(periodic.energy(x) == 0.0);
  // Bad boxes.
  CHECK_THROWS_AS(periodic.set_box(Vector3d(0.3, L, L), {true, true, true}), cmp::UsageError);
  CHECK_THROWS_AS(periodic.set_box(Vector3d(L, -1, L), {true, true, true}), cmp::UsageError);
  c.contact_distance = 0;
  CHECK_THROWS_AS(VertexFaceContacts(mesh, c), cmp::UsageError);
}

TEST_CASE("hertz-faces: a list kept through a box scaled on every side finds what a fresh one finds",
          "[shell][faces]") {
  // Eight 162-vertex shells in a row, each overlapping its neighbours, in a periodic box; the
  // box is scaled and every shell moved rigidly with its centroid (a compression's affine
  // step). A small scaling keeps the list (no new build) and gives the very bits of a term
  // built afresh at the new box; a large one, or a box scaled unevenly, rebuilds it.
  const auto a = fx::perturbed_icosphere(2, 0.01, 3);
  cmp::mesh::TriMesh m;
  const long nv = a.V.rows(), nf = a.F.rows();
  m.V.resize(8 * nv, 3);
  m.F.resize(8 * nf, 3);
  for (int k = 0; k < 8; ++k) {
    m.V.middleRows(k * nv, nv) = a.V.rowwise() + Eigen::RowVector3d(0.5 + 1.95 * k, 1.5 + 0.03 * k, 1.5);
    m.F.middleRows(k * nf, nf) = a.F.array() + static_cast<int>(k * nv);
  }
  ContactParameters c = parameters(0.1);
  Vector3d box(15.6, 3.0, 3.0);
  c.box = box;
  VertexFaceContacts kept(m, c);
  std::vector<double> x = fx::state(m.V);
  const auto affine = [&](double s) {
    for (int k = 0; k < 8; ++k) {
      Vector3d centroid = Vector3d::Zero();
      for (long v = k * nv; v < (k + 1) * nv; ++v) centroid += Vector3d(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
      centroid /= static_cast<double>(nv);
      for (long v = k * nv; v < (k + 1) * nv; ++v)
        for (int d = 0; d < 3; ++d) x[3 * v + d] += (s - 1) * centroid[d];
    }
    box *= s;
  };
  REQUIRE(kept.energy(x) > 0);
  const long first = kept.list_builds();
  for (double s : {0.9995, 0.9995, 1.0004, 0.9990}) {
    affine(s);
    kept.set_box(box, {true, true, true});
    c.box = box;
    const VertexFaceContacts fresh(m, c);
    INFO("scale " << s);
    CHECK(kept.energy(x) == fresh.energy(x));
    CHECK(gradient(kept, x) == gradient(fresh, x));
    CHECK(kept.list_builds() == first);
  }
  affine(0.9);  // each vertex moves from its scaled place by more than the skin allows
  kept.set_box(box, {true, true, true});
  c.box = box;
  CHECK(gradient(kept, x) == gradient(VertexFaceContacts(m, c), x));
  CHECK(kept.list_builds() == first + 1);
  kept.set_box(Vector3d(box[0], box[1] * 1.0001, box[2]), {true, true, true});  // not one factor
  kept.energy(x);
  CHECK(kept.list_builds() == first + 2);
}

TEST_CASE("hertz-faces: the same bits on 1 and 2 threads", "[shell][faces]") {
  // Eight 642-vertex shells in a row along x, each overlapping the next two: 5136 vertices,
  // three fixed chunks.
  const auto a = fx::perturbed_icosphere(4, 0.01, 3), b = fx::perturbed_icosphere(4, 0.01, 4);
  cmp::mesh::TriMesh m;
  const long nv = a.V.rows(), nf = a.F.rows();
  m.V.resize(8 * nv, 3);
  m.F.resize(8 * nf, 3);
  for (int k = 0; k < 8; ++k) {
    m.V.middleRows(k * nv, nv) = (k % 2 ? b.V : a.V).rowwise() + Eigen::RowVector3d(0.97 * k, 0.02 * k, 0);
    m.F.middleRows(k * nf, nf) = a.F.array() + static_cast<int>(k * nv);
  }
  ContactParameters c = parameters(0.05);
  const VertexFaceContacts term(m, c);
  const auto x0 = fx::state(m.V);
  const int saved = omp_get_max_threads();
  // The search runs on all threads only for large systems; this one is made to count as large.
  const long saved_threshold = cmp::shell::ElementAssembly::parallel_elements();
  cmp::shell::ElementAssembly::set_parallel_elements(2048);
  for (double scale : {1.0, 1.01, 1.02}) {
    std::vector<double> x = x0;
    for (double& v : x) v *= scale;
    omp_set_num_threads(1);
    const double e1 = term.energy(x);
    const auto g1 = gradient(term, x);
    const auto k1 = term.touches(x);
    omp_set_num_threads(2);
    const double e2 = term.energy(x);
    const auto g2 = gradient(term, x);
    const auto k2 = term.touches(x);
    CHECK(e1 > 0);
    CHECK(e1 == e2);
    CHECK(g1 == g2);
    // The gradient is that of one pass over the contacts, up to the order of the sums (the
    // records are scattered in fixed slabs, added entry by entry).
    std::vector<double> serial(x.size(), 0.0);
    for (const auto& t : k1) {
      if (!(t.r > 0)) continue;
      const double s = -t.force / t.r;
      for (int a = 0; a < 3; ++a) {
        const double gp = s * t.d[a];
        serial[3 * t.i + a] += gp;
        for (int m = 0; m < 3; ++m) serial[3 * t.corners[m] + a] -= t.weights[m] * gp;
      }
    }
    double largest = 0, off = 0;
    for (std::size_t e = 0; e < x.size(); ++e) {
      largest = std::max(largest, std::abs(serial[e]));
      off = std::max(off, std::abs(g2[e] - serial[e]));
    }
    CHECK(largest > 0);
    CHECK(off <= 1e-13 * largest);
    REQUIRE(k1.size() == k2.size());
    for (std::size_t i = 0; i < k1.size(); ++i) CHECK((k1[i].i == k2[i].i && k1[i].corners == k2[i].corners && k1[i].r == k2[i].r));
  }
  cmp::shell::ElementAssembly::set_parallel_elements(saved_threshold);
  omp_set_num_threads(saved);
}
