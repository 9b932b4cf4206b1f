#pragma once
// Meshes shared by the tests of lib/mesh, each with its exact (polyhedral) area and volume
// where one exists. Built here by hand, independently of the code under test.
#include "core/random.hpp"
#include "mesh/tri_mesh.hpp"

#include <cmath>
#include <vector>

namespace cmp::mesh::fixtures {

// [0,1]^3, 8 vertices, 12 triangles, counter-clockwise seen from outside. Area 6, volume 1.
inline TriMesh unit_cube() {
  TriMesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) m.V.row(i) << (i & 1), (i >> 1) & 1, (i >> 2) & 1;
  m.F.resize(12, 3);
  m.F << 0, 2, 3, 0, 3, 1,  // z = 0, normal -z
      4, 5, 7, 4, 7, 6,     // z = 1, normal +z
      0, 1, 5, 0, 5, 4,     // y = 0, normal -y
      2, 6, 7, 2, 7, 3,     // y = 1, normal +y
      0, 4, 6, 0, 6, 2,     // x = 0, normal -x
      1, 3, 7, 1, 7, 5;     // x = 1, normal +x
  return m;
}

// Regular tetrahedron of edge a centred at the origin. Area sqrt(3) a^2, volume a^3/(6 sqrt 2).
inline TriMesh regular_tetrahedron(double a) {
  TriMesh m;
  m.V.resize(4, 3);
  m.V << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  m.V *= a / (2 * std::sqrt(2.0));
  m.F.resize(4, 3);
  m.F << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  return m;
}

// Vertices +-e_x, +-e_y, +-e_z (0: +x, 1: -x, 2: +y, 3: -y, 4: +z, 5: -z), one face per
// octant. Area 4 sqrt 3, volume 4/3.
inline TriMesh octahedron() {
  TriMesh m;
  m.V.setZero(6, 3);
  for (int a = 0; a < 3; ++a) m.V(2 * a, a) = 1, m.V(2 * a + 1, a) = -1;
  m.F.resize(8, 3);
  int f = 0;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const int x = sx, y = 2 + sy, z = 4 + sz;  // sx = 1 means the negative side
        if ((sx + sy + sz) % 2 == 0)
          m.F.row(f++) << x, y, z;
        else
          m.F.row(f++) << x, z, y;
      }
  return m;
}

// Area and volume of a polyhedral solid of revolution: the closed profile polygon
// (rho_k, z_k) in a meridian half-plane, swept through n equal sectors with straight chords.
// Each sector's faces are planar isosceles trapezoids (triangles where rho = 0); the sector of
// the solid is {rho (t e0 + (1-t) e1) + z e_z} whose volume is sin(2 pi/n) int rho dA.
struct Revolution {
  double area = 0, volume = 0;
};
inline Revolution revolution(const std::vector<double>& rho, const std::vector<double>& z, int n, bool closed) {
  const double half = M_PI / n;
  Revolution r;
  const std::size_t sides = closed ? rho.size() : rho.size() - 1;
  double rho_moment = 0;  // int rho dA over the polygon (shoelace-style, exact for polygons)
  for (std::size_t k = 0; k < sides; ++k) {
    const std::size_t l = (k + 1) % rho.size();
    const double h = std::hypot((rho[l] - rho[k]) * std::cos(half), z[l] - z[k]);
    r.area += n * (rho[k] + rho[l]) * std::sin(half) * h;
    // int rho dA = (1/6) sum (rho_k z_l - rho_l z_k)(rho_k + rho_l), counter-clockwise in (rho, z)
    rho_moment += (rho[k] * z[l] - rho[l] * z[k]) * (rho[k] + rho[l]) / 6;
  }
  r.volume = n * std::sin(2 * half) * std::abs(rho_moment);
  return r;
}

// UV sphere of radius r: poles 0 and last, n_lat - 1 rings of n_lon vertices.
inline TriMesh uv_sphere(int n_lon, int n_lat, double r) {
  TriMesh m;
  const int rings = n_lat - 1;
  m.V.resize(2 + rings * n_lon, 3);
  m.V.row(0) << 0, 0, r;
  for (int k = 1; k <= rings; ++k)
    for (int j = 0; j < n_lon; ++j) {
      const double theta = M_PI * k / n_lat, phi = 2 * M_PI * j / n_lon;
      m.V.row(1 + (k - 1) * n_lon + j) << r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
          r * std::cos(theta);
    }
  const int south = 1 + rings * n_lon;
  m.V.row(south) << 0, 0, -r;
  auto ring = [&](int k, int j) { return 1 + (k - 1) * n_lon + (j % n_lon); };
  std::vector<Eigen::RowVector3i> faces;
  for (int j = 0; j < n_lon; ++j) faces.emplace_back(0, ring(1, j), ring(1, j + 1));
  for (int k = 1; k < rings; ++k)
    for (int j = 0; j < n_lon; ++j) {
      faces.emplace_back(ring(k, j), ring(k + 1, j), ring(k + 1, j + 1));
      faces.emplace_back(ring(k, j), ring(k + 1, j + 1), ring(k, j + 1));
    }
  for (int j = 0; j < n_lon; ++j) faces.emplace_back(south, ring(rings, j + 1), ring(rings, j));
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) m.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  return m;
}

inline Revolution uv_sphere_exact(int n_lon, int n_lat, double r) {
  std::vector<double> rho, z;
  for (int k = 0; k <= n_lat; ++k) {
    rho.push_back(r * std::sin(M_PI * k / n_lat));
    z.push_back(r * std::cos(M_PI * k / n_lat));
  }
  rho.front() = rho.back() = 0;
  return revolution(rho, z, n_lon, false);
}

// Torus of major radius R and minor radius r, n_u sectors around the axis, n_v around the tube.
inline TriMesh torus(int n_u, int n_v, double R, double r) {
  TriMesh m;
  m.V.resize(n_u * n_v, 3);
  auto id = [&](int i, int k) { return (i % n_u) * n_v + (k % n_v); };
  for (int i = 0; i < n_u; ++i)
    for (int k = 0; k < n_v; ++k) {
      const double u = 2 * M_PI * i / n_u, v = 2 * M_PI * k / n_v, rho = R + r * std::cos(v);
      m.V.row(id(i, k)) << rho * std::cos(u), rho * std::sin(u), r * std::sin(v);
    }
  m.F.resize(2 * n_u * n_v, 3);
  int f = 0;
  for (int i = 0; i < n_u; ++i)
    for (int k = 0; k < n_v; ++k) {
      m.F.row(f++) << id(i, k), id(i + 1, k), id(i + 1, k + 1);
      m.F.row(f++) << id(i, k), id(i + 1, k + 1), id(i, k + 1);
    }
  return m;
}

inline Revolution torus_exact(int n_u, int n_v, double R, double r) {
  std::vector<double> rho, z;
  for (int k = 0; k < n_v; ++k) {
    rho.push_back(R + r * std::cos(2 * M_PI * k / n_v));
    z.push_back(r * std::sin(2 * M_PI * k / n_v));
  }
  return revolution(rho, z, n_u, true);
}

// Moebius strip of n quads (2n vertices, 2n triangles) around a circle of radius R, width 2w.
// Quad k joins rungs k and k + 1; the last quad joins rung n - 1 to rung 0 turned over.
inline TriMesh moebius_strip(int n, double R, double w) {
  TriMesh m;
  m.V.resize(2 * n, 3);
  for (int k = 0; k < n; ++k)
    for (int side = 0; side < 2; ++side) {
      const double u = 2 * M_PI * k / n, s = side == 0 ? w : -w, rho = R + s * std::cos(u / 2);
      m.V.row(2 * k + side) << rho * std::cos(u), rho * std::sin(u), s * std::sin(u / 2);
    }
  m.F.resize(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    const int t0 = 2 * k, b0 = 2 * k + 1;
    const int t1 = k + 1 < n ? 2 * (k + 1) : 1, b1 = k + 1 < n ? 2 * (k + 1) + 1 : 0;  // turned over
    m.F.row(2 * k) << t0, b0, b1;
    m.F.row(2 * k + 1) << t0, b1, t1;
  }
  return m;
}

// Three triangles sharing the edge (0, 1): not a manifold.
inline TriMesh three_triangles_on_one_edge() {
  TriMesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  m.F.resize(3, 3);
  m.F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  return m;
}

// The 3-4-5 right triangle in the plane z = 0: area 6, normal +z.
inline TriMesh single_triangle() {
  TriMesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 3, 0, 0, 0, 4, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  return m;
}

inline void flip_face(FaceMatrix& F, Eigen::Index f) { std::swap(F(f, 1), F(f, 2)); }

inline FaceMatrix flipped_all(FaceMatrix F) {
  for (Eigen::Index f = 0; f < F.rows(); ++f) flip_face(F, f);
  return F;
}

inline TriMesh translated(TriMesh m, const Eigen::RowVector3d& t) {
  m.V.rowwise() += t;
  return m;
}

}  // namespace cmp::mesh::fixtures
