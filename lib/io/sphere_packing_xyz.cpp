#include "io/sphere_packing_xyz.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"
#include "io/input.hpp"
#include "io/key_value_line.hpp"
#include "io/line_reader.hpp"
#include "io/parse_number.hpp"
#include "io/xyz.hpp"
#include "io/xyz_frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace cmp::io {

namespace {

[[noreturn]] void fail_at(const XyzFrame& frame, long line, const std::string& what) {
  if (frame.file.empty()) throw std::invalid_argument("extended XYZ frame: " + what);
  throw InputError(frame.file, line, what);
}

const XyzColumn& radius_column(const XyzFrame& frame) {
  for (const auto& wanted : radius_column_names())
    for (const auto& c : frame.columns)
      if (same_key(c.name, wanted)) {
        if ((c.type != 'R' && c.type != 'I') || c.width != 1)
          frame.fail(fmt::format("radius column {}:{}:{}: expected one real number per atom "
                                 "({}:R:1)",
                                 c.name, c.type, c.width, c.name));
        return c;
      }
  frame.fail("no radius column (Properties=...:radius:R:1; OVITO's Radius and ASE's radii are "
             "read too)");
}

// The first particle (in file order) lying within 1e-9 of the summed radii of an earlier
// one, or -1. Points are hashed on a grid of cells at least as wide as the largest such
// distance, so only the 27 cells around a point need a look: O(N).
long first_duplicate(const mesh::VertexMatrix& x, const Eigen::VectorXd& r,
                     const Eigen::Vector3d& box, const std::array<bool, 3>& pbc) {
  const int n = static_cast<int>(x.rows());
  if (n < 2) return -1;
  const double reach = 2e-9 * r.maxCoeff();
  const double extent = std::max(x.cwiseAbs().maxCoeff(), box.maxCoeff());
  const double h = std::max({reach, 1e-14 * extent, DBL_MIN});
  std::array<double, 3> cell{};
  std::array<std::int64_t, 3> cells{};  // number of cells along a periodic axis
  for (int a = 0; a < 3; ++a) {
    // Periodic axes: an integer number of cells tiles the box, so neighbours wrap exactly.
    cells[a] = pbc[a] ? std::max<std::int64_t>(1, static_cast<std::int64_t>(box[a] / h)) : 0;
    cell[a] = pbc[a] ? box[a] / static_cast<double>(cells[a]) : h;
  }
  struct Key {
    std::int64_t c[3];
    bool operator==(const Key& o) const { return c[0] == o.c[0] && c[1] == o.c[1] && c[2] == o.c[2]; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ULL;
      for (auto v : k.c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
      return static_cast<std::size_t>(h);
    }
  };
  std::unordered_map<Key, std::vector<int>, Hash> grid;
  grid.reserve(static_cast<std::size_t>(n));
  const auto key_of = [&](int i) {
    Key k{};
    for (int a = 0; a < 3; ++a) {
      double w = x(i, a);
      if (pbc[a]) w = wrap_into_period(w, box[a]);
      auto c = static_cast<std::int64_t>(std::floor(w / cell[a]));
      if (pbc[a]) c = std::clamp<std::int64_t>(c, 0, cells[a] - 1);
      k.c[a] = c;
    }
    return k;
  };
  for (int i = 0; i < n; ++i) {
    const Key k = key_of(i);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          Key q{{k.c[0] + dx, k.c[1] + dy, k.c[2] + dz}};
          for (int a = 0; a < 3; ++a)
            if (pbc[a]) q.c[a] = ((q.c[a] % cells[a]) + cells[a]) % cells[a];
          const auto it = grid.find(q);
          if (it == grid.end()) continue;
          for (const int j : it->second) {
            double d2 = 0;
            for (int a = 0; a < 3; ++a) {
              double d = x(i, a) - x(j, a);
              if (pbc[a]) d = minimum_image(d, box[a]);
              d2 += d * d;
            }
            if (std::sqrt(d2) < 1e-9 * (r[i] + r[j])) return i;
          }
        }
    grid[k].push_back(i);
  }
  return -1;
}

}  // namespace

const std::vector<std::string>& radius_column_names() {
  static const std::vector<std::string> names{"radius", "radii"};
  return names;
}

const std::string* SpherePackingFrame::find_info(const std::string& key) const {
  for (const auto& [k, v] : info)
    if (k == key) return &v;
  return nullptr;
}

std::optional<double> SpherePackingFrame::positive_info(const std::string& key) const {
  const auto* text = find_info(key);
  if (!text) return std::nullopt;
  const long comment_line = line + 1;
  double v = 0;
  if (!try_parse_double(*text, v) || !(v > 0)) {
    const auto what = fmt::format("{}={} is not a positive number", key, quote_token(*text));
    if (file.empty()) throw std::invalid_argument(what);
    throw InputError(file, comment_line, what);
  }
  return v;
}

SpherePackingFrame sphere_packing_from_frame(const XyzFrame& frame, PbcRule rule) {
  if (!frame.has_lattice) frame.fail("no Lattice=\"...\": a sphere packing needs its box");
  const Eigen::Matrix3d& a = frame.lattice;
  if (a(0, 1) != 0 || a(0, 2) != 0 || a(1, 0) != 0 || a(1, 2) != 0 || a(2, 0) != 0 || a(2, 1) != 0)
    frame.fail("the Lattice is not an orthorhombic box (off-diagonal entries are not zero; "
               "only axis-aligned boxes are supported)");
  if (!(a(0, 0) > 0 && a(1, 1) > 0 && a(2, 2) > 0)) frame.fail("the Lattice has a side that is not positive");
  // Sizes made from the box (its volume, cell lists, voxel grids) must stay finite doubles.
  if (!(a.diagonal().maxCoeff() <= kMaxCoordinate))
    fail_at(frame, frame.line + 1,  // the comment line that holds the Lattice
            fmt::format("the Lattice has a side of {:g}, beyond {:g}: the volumes and distances made from it "
                        "would overflow", a.diagonal().maxCoeff(), kMaxCoordinate));
  if (rule == PbcRule::require_all && !(frame.pbc[0] && frame.pbc[1] && frame.pbc[2]))
    frame.fail("pbc is not \"T T T\": a periodic packing is needed");
  SpherePackingFrame p;
  p.file = frame.file;
  p.line = frame.line;
  p.box = a.diagonal();
  p.pbc = frame.pbc;
  p.info = frame.info;
  const auto& rc = radius_column(frame);
  p.centres = frame.positions();
  p.radius_column = rc.name;
  p.radii = Eigen::Map<const Eigen::VectorXd>(rc.values.data(), static_cast<Eigen::Index>(rc.values.size()));
  if (p.size() == 0) frame.fail("the frame has no spheres");
  const long first_atom_line = frame.line + 2;
  for (int i = 0; i < p.size(); ++i) {
    if (!(p.radii[i] > 0) || !std::isfinite(p.radii[i]))
      fail_at(frame, first_atom_line + i,
              fmt::format("radius {} is not a positive number (column '{}')", p.radii[i], rc.name));
    if (!(p.radii[i] <= kMaxCoordinate) || !(p.centres.row(i).cwiseAbs().maxCoeff() <= kMaxCoordinate))
      fail_at(frame, first_atom_line + i,
              fmt::format("a position or radius is beyond {:g}: the distances and volumes made from it would "
                          "overflow", kMaxCoordinate));
  }
  const long dup = first_duplicate(p.centres, p.radii, p.box, p.pbc);
  if (dup >= 0)
    fail_at(frame, first_atom_line + dup,
            "particle duplicates another one (centres closer than 1e-9 of their radii)");
  return p;
}

std::vector<SpherePackingFrame> read_sphere_packing_xyz(const std::string& path, PbcRule rule) {
  Input input(path);
  return read_sphere_packing_xyz(input, rule);
}

std::vector<SpherePackingFrame> read_sphere_packing_xyz(Input& input, PbcRule rule) {
  XyzReader reader(input);
  std::vector<SpherePackingFrame> packings;
  XyzFrame frame;
  while (reader.next(frame)) packings.push_back(sphere_packing_from_frame(frame, rule));
  return packings;
}

}  // namespace cmp::io
