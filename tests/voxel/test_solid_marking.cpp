#include "voxel/solid_marking.hpp"

#include "spheremesh/subdivision.hpp"
#include "voxel/grid.hpp"
#include "voxel/label_components.hpp"
#include "voxel/percolation.hpp"
#include "voxel/porosity.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

using namespace cmp::voxel;

namespace {

// One sphere of radius r in a periodic cubic cell of side a: the simple cubic array. The
// sphere is centred on a corner, so the cell holds eight pieces of it (periodic wrapping).
std::vector<std::uint8_t> simple_cubic(double a, double r, double delta, SphereMarking m, VoxelGrid& g) {
  g = make_grid(Eigen::Vector3d::Constant(a), delta);
  std::vector<std::uint8_t> pore(g.size(), 1);
  cmp::mesh::VertexMatrix c(1, 3);
  c << 0, 0, 0;
  mark_spheres(c, Eigen::VectorXd::Constant(1, r), g, m, pore);
  return pore;
}

// Does the void of an n x n x n block of cells (the image tiled) percolate along x?
bool percolates_x(double a, double r, double delta, SphereMarking m) {
  const int cells = 2;
  const auto g = make_grid(Eigen::Vector3d::Constant(cells * a), delta);
  std::vector<std::uint8_t> pore(g.size(), 1);
  cmp::mesh::VertexMatrix c(cells * cells * cells, 3);
  int k = 0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int l = 0; l < cells; ++l) c.row(k++) << i * a, j * a, l * a;
  mark_spheres(c, Eigen::VectorXd::Constant(c.rows(), r), g, m, pore);
  std::vector<std::int32_t> labels;
  const int n = label_components(pore.data(), g.dims, labels);
  return spanning_count(label_face_flags(labels, g.dims, n), 0) > 0;
}

}  // namespace

TEST_CASE("simple cubic spheres: voxel porosity converges to 1 - 4 pi r^3 / 3 a^3", "[voxel][marking]") {
  const double a = 1.0, r = 0.4, exact = 1 - 4 * M_PI * r * r * r / (3 * a * a * a);
  VoxelGrid g;
  // Overlap marking: the solid grows by a layer of about half a voxel, so the error is first
  // order, ~ -(surface) * c * delta with c = 0.5 * mean |n|_1-ish = 0.75 for a sphere.
  std::vector<double> errors;
  for (double delta : {0.04, 0.02, 0.01}) {
    const double phi = voxel_porosity(simple_cubic(a, r, delta, SphereMarking::Overlap, g));
    errors.push_back(exact - phi);
    CHECK(phi < exact);  // conservative: never more void than the truth
    const double first_order = 4 * M_PI * r * r * 0.75 * delta;
    CHECK(exact - phi == Approx(first_order).epsilon(0.1));
  }
  CHECK(errors[0] / errors[1] == Approx(2).epsilon(0.05));
  CHECK(errors[1] / errors[2] == Approx(2).epsilon(0.05));
  // Centre marking: no bias at first order; the error is a lattice-point count error, far
  // below the overlap layer and well within delta^1.5 here.
  for (double delta : {0.04, 0.02, 0.01}) {
    const double phi = voxel_porosity(simple_cubic(a, r, delta, SphereMarking::Centre, g));
    CHECK(std::abs(phi - exact) < 2 * std::pow(delta, 1.5));
  }
}

TEST_CASE("simple cubic spheres percolate exactly while r < a / sqrt 2", "[voxel][marking]") {
  const double a = 1.0, rc = a / std::sqrt(2.0);
  for (double delta : {0.05, 0.025}) {
    INFO("delta " << delta);
    // Overlap marking keeps only voxels of the true void: none percolates at r >= a / sqrt 2.
    CHECK(!percolates_x(a, rc * (1 + 1e-9), delta, SphereMarking::Overlap));
    // and percolates once the channel is wider than a voxel diagonal.
    CHECK(percolates_x(a, rc - std::sqrt(3.0) * delta, delta, SphereMarking::Overlap));
    CHECK(percolates_x(a, 0.45, delta, SphereMarking::Overlap));  // touching spheres (r > a/2) still percolate
    // Centre marking: the void percolates a little beyond rc, by less than a voxel.
    CHECK(!percolates_x(a, rc + delta, delta, SphereMarking::Centre));
    CHECK(percolates_x(a, rc - delta, delta, SphereMarking::Centre));
  }
}

TEST_CASE("a closed shell is impermeable with triangle marking and leaks with vertex marking", "[voxel][marking]") {
  // Icosahedral sphere mesh of radius 1, level 4 (642 vertices, edges ~0.19): at delta = 0.05,
  // far below the edge length, vertices alone leave holes (the thesis's caveat, 5.2.2).
  const auto m = cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 4, 1.0);
  cmp::mesh::VertexMatrix V = m.V;
  V.rowwise() += Eigen::RowVector3d(1.5, 1.5, 1.5);
  const auto g = make_grid(Eigen::Vector3d::Constant(3.0), 0.05);
  const std::size_t centre = g.index(30, 30, 30), corner = g.index(0, 0, 0);
  for (ShellMarking method : {ShellMarking::Triangles, ShellMarking::Vertices}) {
    std::vector<std::uint8_t> pore(g.size(), 1);
    mark_shells(V, m.F, g, method, 0.0, pore);
    std::vector<std::int32_t> labels;
    const int n = label_components(pore.data(), g.dims, labels);
    INFO(shell_marking_name(method) << ": " << n << " components");
    REQUIRE(labels[centre] != 0);
    if (method == ShellMarking::Triangles) {
      CHECK(labels[centre] != labels[corner]);
      // the solid voxels form a thin layer around the sphere: about 4 pi R^2 / delta^2 * ~1.5
      long solid = 0;
      for (auto v : pore) solid += v == 0;
      CHECK(solid > 4 * M_PI / (0.05 * 0.05));
    } else {
      CHECK(labels[centre] == labels[corner]);
    }
  }
  // Thickening by a vertex radius closes the holes of vertex marking again.
  std::vector<std::uint8_t> pore(g.size(), 1);
  mark_shells(V, m.F, g, ShellMarking::Vertices, 0.1, pore);
  std::vector<std::int32_t> labels;
  label_components(pore.data(), g.dims, labels);
  CHECK(labels[centre] != labels[corner]);
}

TEST_CASE("shells crossing a periodic face are wrapped", "[voxel][marking]") {
  // The same sphere centred at the box corner: its eight pieces must close the corner region.
  const auto m = cmp::spheremesh::subdivided_sphere(cmp::spheremesh::Subdivision::Icosahedron, 4, 1.0);
  const auto g = make_grid(Eigen::Vector3d::Constant(3.0), 0.05);
  std::vector<std::uint8_t> pore(g.size(), 1);
  mark_shells(m.V, m.F, g, ShellMarking::Triangles, 0.0, pore);
  std::vector<std::int32_t> labels;
  LabelOptions periodic;
  periodic.periodic = {true, true, true};
  const int n = label_components(pore.data(), g.dims, labels, periodic);
  CHECK(n == 2);  // inside (around the corner) and outside
  CHECK(labels[g.index(0, 0, 0)] != labels[g.index(30, 30, 30)]);
  CHECK(labels[g.index(0, 0, 0)] == labels[g.index(59, 59, 59)]);
  // The eight wrapped pieces enclose the sphere's volume less the marked layer (~1-2 voxels
  // thick over the area 4 pi).
  long inside = 0;
  for (auto l : labels) inside += l == labels[0];
  const double v = inside * std::pow(0.05, 3);
  CHECK(v < 4 * M_PI / 3);
  CHECK(v > 4 * M_PI / 3 - 4 * M_PI * 2 * 0.05);
}

TEST_CASE("marking method names", "[voxel][marking]") {
  CHECK(shell_marking_from_name("vertices") == ShellMarking::Vertices);
  CHECK(shell_marking_name(ShellMarking::Triangles) == "triangles");
  CHECK_THROWS(shell_marking_from_name("faces"));
  CHECK(sphere_marking_from_name("centre") == SphereMarking::Centre);
  CHECK_THROWS(sphere_marking_from_name("inside"));
}

namespace {

// Exact area of the disc of radius rho centred in the square [-a, a]^2.
double disc_in_square(double rho, double a) {
  if (rho <= 0) return 0;
  if (rho <= a) return M_PI * rho * rho;
  if (rho >= a * std::sqrt(2.0)) return 4 * a * a;
  auto F = [rho](double x) { return 0.5 * (x * std::sqrt(std::max(0.0, rho * rho - x * x)) + rho * rho * std::asin(x / rho)); };
  const double x0 = std::sqrt(rho * rho - a * a);
  return 4 * (a * x0 + F(a) - F(x0));
}

// Exact volume of the ball of radius r centred in the cube [-a, a]^3: the solid of one sphere
// in a periodic cubic cell of side 2a (the cube is the sphere's nearest-image cell). The area
// of a slice is closed-form; the integral over z is Gauss-Legendre on panels between the
// kinks (|z| = r, sqrt(r^2 - a^2), sqrt(r^2 - 2 a^2)), accurate to ~1e-12.
double ball_in_cube(double r, double a) {
  std::vector<double> cuts{0.0, std::min(r, a)};
  for (double k : {1.0, 2.0})
    if (r * r - k * a * a > 0 && std::sqrt(r * r - k * a * a) < cuts[1]) cuts.push_back(std::sqrt(r * r - k * a * a));
  std::sort(cuts.begin(), cuts.end());
  static const double x[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                              0.2369268850561891};
  double v = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const int panels = 4000;
    const double h = (cuts[c + 1] - cuts[c]) / panels;
    for (int p = 0; p < panels; ++p)
      for (int q = 0; q < 5; ++q) {
        const double z = cuts[c] + h * (p + 0.5 + 0.5 * x[q]);
        v += 0.5 * h * w[q] * disc_in_square(std::sqrt(std::max(0.0, r * r - z * z)), a);
      }
  }
  return 2 * v;  // both halves in z
}

// Void fraction of one sphere of radius r at `centre` in the periodic unit cube, voxelised.
double one_sphere_porosity(double r, double delta, SphereMarking m, const Eigen::Vector3d& centre) {
  const auto g = make_grid(Eigen::Vector3d::Ones(), delta);
  std::vector<std::uint8_t> pore(g.size(), 1);
  cmp::mesh::VertexMatrix c(1, 3);
  c.row(0) = centre.transpose();
  mark_spheres(c, Eigen::VectorXd::Constant(1, r), g, m, pore);
  return voxel_porosity(pore);
}

}  // namespace

TEST_CASE("the exact ball-in-cube volume has the right limits", "[voxel][marking]") {
  CHECK(ball_in_cube(0.3, 0.5) == Approx(4 * M_PI / 3 * 0.027).epsilon(1e-12));
  CHECK(ball_in_cube(0.9, 0.5) == Approx(1).epsilon(1e-12));
  // r = a sqrt 2: the ball less six caps of height r - a
  const double r = 0.5 * std::sqrt(2.0), h = r - 0.5;
  CHECK(ball_in_cube(r, 0.5) == Approx(4 * M_PI / 3 * r * r * r - 6 * M_PI * h * h * (3 * r - h) / 3).epsilon(1e-10));
}

TEST_CASE("one sphere larger than half the periodic cell is marked in every image", "[voxel][marking]") {
  // The solid of one sphere in a periodic unit cell is the ball clipped to its nearest-image
  // cube. Overlap marking makes every voxel touching the ball solid, so its void lies between
  // the exact void at r + sqrt 3 delta and at r; centre marking between r +- sqrt 3 delta / 2.
  const double delta = 0.02, diag = std::sqrt(3.0) * delta;
  auto exact = [](double r) { return 1 - ball_in_cube(r, 0.5); };
  for (const Eigen::Vector3d& centre : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.31, 0.47, 0.73)}) {
    for (double r : {0.3, 0.45, 0.55, 0.68, 0.74, 0.8, 0.85}) {
      INFO("r " << r << " centre " << centre.transpose());
      const double overlap = one_sphere_porosity(r, delta, SphereMarking::Overlap, centre);
      CHECK(overlap <= exact(r) + 1e-12);
      CHECK(overlap >= exact(r + diag) - 1e-12);
      const double c = one_sphere_porosity(r, delta, SphereMarking::Centre, centre);
      CHECK(c <= exact(r - diag / 2) + 1e-12);
      CHECK(c >= exact(r + diag / 2) - 1e-12);
      CHECK(c == Approx(exact(r)).margin(3e-3));
    }
  }
}

TEST_CASE("one sphere in a periodic unit cell percolates exactly while r < 1 / sqrt 2", "[voxel][marking]") {
  const double rc = 1 / std::sqrt(2.0);
  auto percolates = [](double r, double delta, SphereMarking m, const Eigen::Vector3d& centre) {
    const auto g = make_grid(Eigen::Vector3d::Ones(), delta);
    std::vector<std::uint8_t> pore(g.size(), 1);
    cmp::mesh::VertexMatrix c(1, 3);
    c.row(0) = centre.transpose();
    mark_spheres(c, Eigen::VectorXd::Constant(1, r), g, m, pore);
    std::vector<std::int32_t> labels;
    const int n = label_components(pore.data(), g.dims, labels);
    return spanning_count(label_face_flags(labels, g.dims, n), 0) > 0;
  };
  for (double delta : {0.02, 0.01}) {
    for (const Eigen::Vector3d& centre : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0.5, 0.5)}) {
      INFO("delta " << delta << " centre " << centre.transpose());
      CHECK(!percolates(rc * (1 + 1e-9), delta, SphereMarking::Overlap, centre));
      CHECK(!percolates(0.74, delta, SphereMarking::Overlap, centre));
      CHECK(!percolates(rc + delta, delta, SphereMarking::Centre, centre));
      CHECK(!percolates(0.74, delta, SphereMarking::Centre, centre));
      CHECK(percolates(rc - std::sqrt(3.0) * delta, delta, SphereMarking::Overlap, centre));
      CHECK(percolates(rc - delta, delta, SphereMarking::Centre, centre));
    }
  }
}

TEST_CASE("a triangle longer than the periodic box is marked in every image", "[voxel][marking]") {
  // One thin triangle 1.8 box lengths long in the plane z = 0.5 of a periodic unit cell, against
  // the same triangle cut into 64 pieces shorter than half the box: the same solid voxels.
  const auto g = make_grid(Eigen::Vector3d::Ones(), 0.02);
  const Eigen::Vector3d a(-0.2, 0.3, 0.5013), b(1.6, 0.3, 0.5013), c(1.6, 0.7, 0.5013);
  cmp::mesh::VertexMatrix V(3, 3);
  V << a.transpose(), b.transpose(), c.transpose();
  cmp::mesh::FaceMatrix F(1, 3);
  F << 0, 1, 2;
  // 8 x 8 sub-triangles by barycentric subdivision of the edges
  const int n = 8;
  cmp::mesh::VertexMatrix Vs((n + 1) * (n + 2) / 2, 3);
  std::vector<std::array<int, 2>> ij;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      Vs.row(static_cast<long>(ij.size())) = (a + (b - a) * i / n + (c - a) * j / n).transpose();
      ij.push_back({i, j});
    }
  auto at = [&](int i, int j) {
    for (std::size_t k = 0; k < ij.size(); ++k)
      if (ij[k][0] == i && ij[k][1] == j) return static_cast<int>(k);
    return -1;
  };
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      faces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < n) faces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  cmp::mesh::FaceMatrix Fs(static_cast<long>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) Fs.row(static_cast<long>(f)) << faces[f][0], faces[f][1], faces[f][2];
  REQUIRE(Fs.rows() == n * n);
  std::vector<std::uint8_t> whole(g.size(), 1), pieces(g.size(), 1);
  mark_shells(V, F, g, ShellMarking::Triangles, 0.0, whole);
  mark_shells(Vs, Fs, g, ShellMarking::Triangles, 0.0, pieces);
  long solid = 0, differ = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    solid += whole[i] == 0;
    differ += whole[i] != pieces[i];
  }
  CHECK(differ == 0);
  CHECK(solid > 0);
  // (0.31, 0.61, 0.5) is covered only by the image of the triangle at x = 1.31
  CHECK(whole[g.index(15, 30, 25)] == 0);
  // thickened: a vertex with thickness larger than half the box makes every voxel solid
  std::vector<std::uint8_t> all(g.size(), 1);
  cmp::mesh::VertexMatrix p(1, 3);
  p << 0.1, 0.2, 0.3;
  mark_shells(p, cmp::mesh::FaceMatrix(0, 3), g, ShellMarking::Vertices, 0.55, all);
  CHECK(std::count(all.begin(), all.end(), 1) == 0);
}
