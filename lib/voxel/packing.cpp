#include "voxel/packing.hpp"

#include "core/errors.hpp"
#include "io/off.hpp"
#include "io/parse_number.hpp"
#include "io/xyz.hpp"
#include "voxel/porosity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <queue>

namespace cmp::voxel {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

double parse_d0(const std::string& text, const std::string& file, long line) {
  double v = 0;
  try {
    v = std::stod(text);
  } catch (...) {
    throw InputError(file, line, "D0='" + text + "' is not a number");
  }
  if (!(v > 0) || !std::isfinite(v)) throw InputError(file, line, "D0=" + text + " is not positive");
  return v;
}

Packing read_shells(const std::string& path) {
  auto off = io::read_off(path);
  Packing p;
  p.kind = Packing::Kind::Shells;
  p.file = path;
  if (!off.packing.box) throw InputError(path, 1, "no '# box Lx Ly Lz' line: not a packing OFF (DESIGN.md)");
  p.box = *off.packing.box;
  p.periodic = off.packing.periodic;
  // Without '# periodic' the reader says "not periodic"; a packing of shellpack is periodic
  // and says so. We take the file's word.
  p.shell_offsets = io::shell_vertex_offsets(off.packing);
  if (p.shell_offsets.empty()) p.shell_offsets = {0, static_cast<int>(off.V.rows())};  // one shell
  p.V = std::move(off.V);
  p.F = std::move(off.F);
  if (p.F.rows() == 0) throw InputError(path, 0, "the packing has no triangles");
  unwrap_shells(p.V, p.F, p.shell_offsets, p.box, p.periodic);
  for (const auto& c : off.comments)
    if (c.rfind("D0=", 0) == 0 || c.rfind("d0=", 0) == 0) {
      p.d0 = parse_d0(c.substr(3), path, 0);
      p.d0_source = "file";
    }
  if (p.d0_source.empty()) {
    const auto vols = shell_volumes(p.V, p.F, p.shell_offsets);
    double mean = 0;
    for (double v : vols) mean += v;
    mean /= static_cast<double>(vols.size());
    if (!(mean > 0)) throw InputError(path, 0, "shell volumes are not positive (faces oriented inward?); give --d0");
    p.d0 = std::cbrt(6 * mean / M_PI);
    p.d0_source = "shell_volume";
  }
  return p;
}

Packing read_spheres(const std::string& path, double scale) {
  const auto frames = io::read_xyz(path);
  const auto& f = frames.back();
  Packing p;
  p.kind = Packing::Kind::Spheres;
  p.file = path;
  if (!f.has_lattice) f.fail("no Lattice=\"...\": the box of the packing is needed");
  const Eigen::Matrix3d& L = f.lattice;
  if (std::abs(L(0, 1)) + std::abs(L(0, 2)) + std::abs(L(1, 0)) + std::abs(L(1, 2)) + std::abs(L(2, 0)) +
          std::abs(L(2, 1)) != 0)
    f.fail("the Lattice is not orthorhombic (only axis-aligned boxes are supported)");
  p.box = L.diagonal();
  if (!(p.box.minCoeff() > 0)) f.fail("the Lattice has a side that is not positive");
  p.periodic = f.pbc;
  p.centres = f.positions();
  const auto& rcol = f.column("radius", 'R', 1);
  p.radii = Eigen::Map<const Eigen::VectorXd>(rcol.values.data(), static_cast<long>(rcol.values.size()));
  for (long i = 0; i < p.radii.size(); ++i)
    if (!(p.radii[i] > 0) || !std::isfinite(p.radii[i]))
      throw InputError(path, f.line + 2 + i, fmt::format("radius {} is not positive", p.radii[i]));
  if (p.radii.size() == 0) f.fail("the frame has no spheres");
  if (const auto* d0 = f.find_info("D0")) {
    p.d0 = parse_d0(*d0, path, f.line + 1);
    p.d0_source = "file";
  } else {
    p.d0 = 2 * p.radii.mean();
    p.d0_source = "mean_diameter";
  }
  p.scale = scale;
  p.radii *= scale;
  return p;
}

}  // namespace

Packing read_packing(const std::string& path, const PackingReadOptions& options) {
  const bool xyz = ends_with(path, ".xyz") || ends_with(path, ".extxyz");
  Packing p = xyz ? read_spheres(path, options.scale) : read_shells(path);
  if (options.d0 > 0) {
    p.d0 = options.d0;
    p.d0_source = "option";
  }
  return p;
}

void unwrap_shells(mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const std::vector<int>& offsets,
                   const Eigen::Vector3d& box, std::array<bool, 3> periodic) {
  if (!periodic[0] && !periodic[1] && !periodic[2]) return;
  const int n = static_cast<int>(V.rows());
  std::vector<std::vector<int>> adjacent(n);
  for (int f = 0; f < F.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      adjacent[F(f, e)].push_back(F(f, (e + 1) % 3));
      adjacent[F(f, (e + 1) % 3)].push_back(F(f, e));
    }
  std::vector<char> seen(n, 0);
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
    for (int start = offsets[k]; start < offsets[k + 1]; ++start) {  // every piece of the shell
      if (seen[start] || adjacent[start].empty()) continue;
      std::queue<int> todo;
      todo.push(start);
      seen[start] = 1;
      while (!todo.empty()) {
        const int v = todo.front();
        todo.pop();
        for (int w : adjacent[v]) {
          if (seen[w]) continue;
          seen[w] = 1;
          for (int a = 0; a < 3; ++a)
            if (periodic[a]) {
              const double d = V(w, a) - V(v, a);
              V(w, a) -= box[a] * std::nearbyint(d / box[a]);
            }
          todo.push(w);
        }
      }
    }
}

}  // namespace cmp::voxel
