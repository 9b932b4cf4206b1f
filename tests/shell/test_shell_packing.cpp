// Shells built from a sphere packing, and the check that they do not pass through each other.
#include "shell/compression.hpp"
#include "shell/penetration.hpp"
#include "shell/shell_contact_forces.hpp"
#include "shell/shell_packing.hpp"

#include "shell_fixtures.hpp"

#include "core/errors.hpp"
#include "mesh/enclosed_volume.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace cmp::shell;
namespace fx = cmp::shell::fixtures;

namespace {

// Three spheres in a periodic box of side 6: radii 1, 1, 2 (so <r> = 4/3, D_0 = 8/3 units).
cmp::io::SpherePackingFrame three_spheres() {
  cmp::io::SpherePackingFrame p;
  p.box = Eigen::Vector3d(6, 6, 6);
  p.centres.resize(3, 3);
  p.centres << 1, 1, 1, 3.5, 1, 1, 1, 4, 4;
  p.radii.resize(3);
  p.radii << 1, 1, 2;
  return p;
}

Eigen::Vector3d centroid(const cmp::mesh::VertexMatrix& V, Eigen::Index first, Eigen::Index count) {
  return V.middleRows(first, count).colwise().mean().transpose();
}

}  // namespace

TEST_CASE("shells sit on their spheres, sized by radius, in the scaled box, each turned its own way",
          "[shell][packing]") {
  const auto cell = normalised_cell(fx::perturbed_icosphere(2, 0.0, 1, 3.0), "cell.off");
  CHECK(cmp::mesh::enclosed_volume(cell.V, cell.F) == Approx(std::numbers::pi / 6).epsilon(1e-12));
  CHECK(cell.V.colwise().mean().norm() < 1e-12);
  const auto spheres = three_spheres();
  const double envelope = 0.1, rest = 0.95;
  const auto p = place_shells(spheres, cell, rest, envelope, 7);
  const double unit = 2.0 * (4.0 / 3.0) / (1 + envelope);  // file units per D_0
  REQUIRE(p.shell_vertex_counts.size() == 3);
  CHECK(p.box.isApprox(Eigen::Vector3d::Constant(6 / unit), 1e-14));
  const Eigen::Index n = cell.V.rows();
  for (int i = 0; i < 3; ++i) {
    INFO("shell " << i);
    CHECK(p.size_factors[i] == Approx(spheres.radii[i] / (4.0 / 3.0)));
    CHECK((centroid(p.mesh.V, i * n, n) - spheres.centres.row(i).transpose() / unit).norm() < 1e-12);
    cmp::mesh::FaceMatrix F = p.mesh.F.middleRows(i * cell.F.rows(), cell.F.rows()).array() - static_cast<int>(i * n);
    const double d = std::cbrt(6 * cmp::mesh::enclosed_volume(p.mesh.V.middleRows(i * n, n), F) / std::numbers::pi);
    CHECK(d == Approx(rest * p.size_factors[i]).epsilon(1e-12));
  }
  // Random rotations: shell 0 and 1 (same size) are not translates of each other; the same
  // seed gives the same packing, another seed another one.
  const Eigen::MatrixXd a = p.mesh.V.middleRows(0, n).rowwise() - centroid(p.mesh.V, 0, n).transpose();
  const Eigen::MatrixXd b = p.mesh.V.middleRows(n, n).rowwise() - centroid(p.mesh.V, n, n).transpose();
  CHECK((a - b).norm() > 0.1);
  CHECK(place_shells(spheres, cell, rest, envelope, 7).mesh.V == p.mesh.V);
  CHECK(place_shells(spheres, cell, rest, envelope, 8).mesh.V != p.mesh.V);
}

TEST_CASE("a cell template must be one closed outward shell", "[shell][packing]") {
  auto m = fx::perturbed_icosphere(1, 0.0, 1);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) std::swap(m.F(f, 1), m.F(f, 2));
  CHECK_THROWS_WITH(normalised_cell(m, "in.off"), Catch::Contains("in.off") && Catch::Contains("oriented inward"));
  auto two = fx::perturbed_icosphere(1, 0.0, 1);
  const auto b = fx::perturbed_icosphere(1, 0.0, 1);
  two.V.conservativeResize(2 * b.V.rows(), 3);
  two.V.bottomRows(b.V.rows()) = b.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  two.F.conservativeResize(2 * b.F.rows(), 3);
  two.F.bottomRows(b.F.rows()) = b.F.array() + static_cast<int>(b.V.rows());
  CHECK_THROWS_WITH(normalised_cell(two, "two.off"), Catch::Contains("one closed shell"));
}

TEST_CASE("penetrations: a vertex inside another shell is found, also through the periodic box",
          "[shell][packing]") {
  // Two unit spheres 2.5 apart (no contact), in a periodic box of side 4.6 along x: through the
  // box they are 2.1 apart, still clear. Moving the second to 1.5 (or 3.1: 1.5 through the box)
  // puts vertices of each inside the other.
  const auto a = fx::perturbed_icosphere(3, 0.0, 1);
  cmp::mesh::TriMesh m;
  m.V.resize(2 * a.V.rows(), 3);
  m.F.resize(2 * a.F.rows(), 3);
  m.V << a.V, a.V;
  m.F << a.F, a.F.array() + static_cast<int>(a.V.rows());
  const auto shells = shell_partition(m.F, static_cast<int>(m.V.rows()));
  const Eigen::Vector3d box(4.6, 10, 10);
  const auto at = [&](double dx) {
    Eigen::VectorXd x(3 * m.V.rows());
    for (Eigen::Index v = 0; v < m.V.rows(); ++v)
      x.segment<3>(3 * v) = m.V.row(v).transpose() + Eigen::Vector3d(v < a.V.rows() ? 0 : dx, 0, 0);
    return x;
  };
  CHECK(penetrations(at(2.5), m.F, shells, box).empty());
  CHECK(penetrations(at(2.5), m.F, shells, std::nullopt).empty());
  const auto near = penetrations(at(1.5), m.F, shells, std::nullopt);
  REQUIRE(!near.empty());
  CHECK(near.front().shell == 0);
  CHECK(near.front().vertex_shell == 1);
  CHECK(penetrations(at(3.1), m.F, shells, std::nullopt).empty());  // open space: 3.1 apart
  CHECK(penetrations(at(3.1), m.F, shells, box).size() == near.size());  // periodic: 1.5 apart
}

TEST_CASE("compress's Z and analyze's contacts count every periodic image of a neighbour", "[shell][packing]") {
  // Two shells on a body-centred cubic lattice of one cell: each faces the other's eight images
  // across the box, 0.002 D0 apart (inside the contact reach of both laws). A count of
  // touching pairs would give Z = 1; each image is a contact of its own: Z = 8.
  const auto cell = normalised_cell(fx::perturbed_icosphere(3, 0.0, 1, 1.0), "cell.off");
  cmp::io::SpherePackingFrame spheres;
  const double L = 1.1, envelope = 0.02;
  spheres.box = Eigen::Vector3d::Constant(L);
  spheres.centres.resize(2, 3);
  spheres.centres << 0, 0, 0, L / 2, L / 2, L / 2;
  spheres.radii = Eigen::VectorXd::Constant(2, 0.5);
  const double gap = 0.002, distance = L * std::sqrt(3.0) / 2 * (1 + envelope);  // centres [D0]
  for (const char* style : {"hertz-faces", "hertz-vertices"}) {
    INFO(style);
    CompressionOptions o;
    o.model.pressure = "volume";
    o.model.material = {1.0, 0.5, 0.02};
    o.model.shell_contact_style = style;
    o.model.contact.contact_distance = envelope;
    o.model.contact.vertex_radius = 0.06;
    o.targets = {0.9};
    const Compression run(place_shells(spheres, cell, distance - gap, envelope, 1), o);
    const CompressionRow row = run.observe();
    CHECK(row.contacts == 8);
    CHECK(row.Z == 8.0);
    CHECK(row.pressure > 0);
    const auto& s = run.system();
    const cmp::mesh::VertexMatrix V = Eigen::Map<const cmp::mesh::VertexMatrix>(s.x.data(), s.vertex_count(), 3);
    cmp::neighbours::Box box;
    box.lengths = run.box();
    box.periodic = {true, true, true};
    const auto contacts = shell_contacts(V, s.rest().F, {0, static_cast<int>(cell.V.rows()), 2 * static_cast<int>(cell.V.rows())},
                                         box, o.model.contact, style);
    CHECK(contacts_per_shell(contacts, 2) == std::vector<int>{8, 8});
  }
}
