#include "spheremesh/subdivision.hpp"

#include "core/errors.hpp"

#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace cmp::spheremesh {

namespace {

using Point = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

struct Polyhedron {
  std::vector<Point> points;  // on the unit sphere
  std::vector<Triangle> triangles;
};

// Orients every triangle of a convex polyhedron centred at the origin outward.
void orient_outward_convex(Polyhedron& p) {
  for (auto& t : p.triangles) {
    const Point& a = p.points[t[0]];
    const Point n = (p.points[t[1]] - a).cross(p.points[t[2]] - a);
    if (n.dot(a + p.points[t[1]] + p.points[t[2]]) < 0) std::swap(t[1], t[2]);
  }
}

Polyhedron base_polyhedron(Subdivision scheme) {
  Polyhedron p;
  switch (scheme) {
    case Subdivision::Simple: {
      // Corners indexed by bits (x, y, z) -> 0/1 meaning -1/+1; every face split by the
      // diagonal through corner 7 = (1,1,1) or corner 0 = (-1,-1,-1).
      for (int c = 0; c < 8; ++c)
        p.points.push_back(Point(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1).normalized());
      // Each face as a quad (a, b, c, d) in cyclic order with a = 0 or 7 the diagonal corner.
      const int quads[6][4] = {{7, 5, 4, 6}, {7, 3, 1, 5}, {7, 6, 2, 3},
                               {0, 1, 3, 2}, {0, 4, 5, 1}, {0, 2, 6, 4}};
      for (const auto& q : quads) {
        p.triangles.push_back({q[0], q[1], q[2]});
        p.triangles.push_back({q[0], q[2], q[3]});
      }
      break;
    }
    case Subdivision::Tetrahedron:
      p.points = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)};
      p.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      break;
    case Subdivision::Octahedron:
      p.points = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                  Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
      for (int x : {0, 1})
        for (int y : {2, 3})
          for (int z : {4, 5}) p.triangles.push_back({x, y, z});
      break;
    case Subdivision::Icosahedron: {
      const double g = (1 + std::sqrt(5.0)) / 2;
      for (double s : {-1.0, 1.0})
        for (double t : {-1.0, 1.0}) {
          p.points.emplace_back(0, s, t * g);
          p.points.emplace_back(s, t * g, 0);
          p.points.emplace_back(t * g, 0, s);
        }
      // The 20 faces are the triples of mutually adjacent vertices (edge length 2).
      const int n = static_cast<int>(p.points.size());
      auto adjacent = [&](int i, int j) { return std::abs((p.points[i] - p.points[j]).norm() - 2) < 1e-9; };
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          for (int k = j + 1; k < n; ++k)
            if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) p.triangles.push_back({i, j, k});
      break;
    }
  }
  for (auto& x : p.points) x.normalize();
  orient_outward_convex(p);
  return p;
}

// Midpoint nodes shared by the two triangles of an edge, created once.
class MidpointCache {
 public:
  explicit MidpointCache(std::vector<Point>& points) : points_(points) {}
  int midpoint(int a, int b) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    auto [it, inserted] = cache_.try_emplace(key, static_cast<int>(points_.size()));
    if (inserted) points_.push_back((0.5 * (points_[a] + points_[b])).normalized());
    return it->second;
  }
 private:
  std::vector<Point>& points_;
  std::unordered_map<std::uint64_t, int> cache_;
};

void quadrisect(Polyhedron& p) {
  MidpointCache mid(p.points);
  std::vector<Triangle> next;
  next.reserve(4 * p.triangles.size());
  for (const auto& [a, b, c] : p.triangles) {
    const int ab = mid.midpoint(a, b), bc = mid.midpoint(b, c), ca = mid.midpoint(c, a);
    next.push_back({a, ab, ca});
    next.push_back({ab, b, bc});
    next.push_back({ca, bc, c});
    next.push_back({ab, bc, ca});
  }
  p.triangles.swap(next);
}

// Splits every triangle at the midpoint of its longest edge. Two triangles sharing an edge
// agree on whether it is their longest, so no node is left hanging; near-ties
// are broken by vertex index so that both sides decide alike.
void bisect_longest_edges(Polyhedron& p) {
  MidpointCache mid(p.points);
  std::vector<Triangle> next;
  next.reserve(2 * p.triangles.size());
  for (const auto& t : p.triangles) {
    int best = 0;
    double best_length = -1;
    std::uint64_t best_key = 0;
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      const double length = (p.points[a] - p.points[b]).squaredNorm();
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const bool tie = std::abs(length - best_length) <= 1e-12 * length;
      if ((!tie && length > best_length) || (tie && key < best_key)) {
        best = e, best_length = length, best_key = key;
      }
    }
    const int a = t[best], b = t[(best + 1) % 3], c = t[(best + 2) % 3];
    const int m = mid.midpoint(a, b);
    next.push_back({a, m, c});
    next.push_back({m, b, c});
  }
  p.triangles.swap(next);
}

}  // namespace

Subdivision subdivision_from_name(const std::string& name) {
  if (name == "simple") return Subdivision::Simple;
  if (name == "tetra") return Subdivision::Tetrahedron;
  if (name == "octa") return Subdivision::Octahedron;
  if (name == "icosa") return Subdivision::Icosahedron;
  throw UsageError("unknown subdivision '" + name + "' (simple, tetra, octa, icosa)");
}

std::string subdivision_name(Subdivision scheme) {
  switch (scheme) {
    case Subdivision::Simple: return "simple";
    case Subdivision::Tetrahedron: return "tetra";
    case Subdivision::Octahedron: return "octa";
    case Subdivision::Icosahedron: return "icosa";
  }
  return "?";
}

namespace {
void check_level(int level) {
  if (level < 1) throw UsageError("level must be at least 1 (the base polyhedron), got " + std::to_string(level));
  if (level > kMaxSubdivisionLevel)
    throw UsageError("level " + std::to_string(level) + " is too fine (more than 10^8 triangles)");
}
}  // namespace

long subdivision_face_count(Subdivision scheme, int level) {
  check_level(level);  // the shifts below are undefined for level < 1
  if (scheme == Subdivision::Simple) return 12L << (level - 1);
  const long base = scheme == Subdivision::Tetrahedron ? 4 : scheme == Subdivision::Octahedron ? 8 : 20;
  return base << (2 * (level - 1));
}

long subdivision_vertex_count(Subdivision scheme, int level) {
  return subdivision_face_count(scheme, level) / 2 + 2;  // Euler: F = 2V - 4
}

mesh::TriMesh subdivided_sphere(Subdivision scheme, int level, double radius) {
  check_level(level);
  if (!(radius > 0) || !std::isfinite(radius)) throw UsageError("radius must be positive");
  Polyhedron p = base_polyhedron(scheme);
  for (int l = 1; l < level; ++l) {
    if (scheme == Subdivision::Simple) bisect_longest_edges(p);
    else quadrisect(p);
  }
  mesh::TriMesh m;
  m.V.resize(static_cast<Eigen::Index>(p.points.size()), 3);
  for (std::size_t i = 0; i < p.points.size(); ++i) m.V.row(i) = radius * p.points[i].transpose();
  m.F.resize(static_cast<Eigen::Index>(p.triangles.size()), 3);
  for (std::size_t f = 0; f < p.triangles.size(); ++f)
    m.F.row(f) << p.triangles[f][0], p.triangles[f][1], p.triangles[f][2];
  return m;
}

}  // namespace cmp::spheremesh
