#include "packing/packing_file.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/input.hpp"
#include "io/line_reader.hpp"
#include "io/off.hpp"
#include "io/parse_number.hpp"
#include "io/sphere_packing_xyz.hpp"
#include "packing/shell_volumes.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <queue>

namespace cmp::packing {

namespace {

double parse_d0(const std::string& text, const std::string& file, long line) {
  double v = 0;
  if (!io::try_parse_double(text, v) || !(v > 0))
    throw InputError(file, line, "D0=" + io::quote_token(text) +
                                     " is not a positive number");
  return v;
}

Packing read_shells(io::Input& input) {
  const auto& path = input.path();
  auto off = io::read_off(input);
  Packing p;
  p.kind = Packing::Kind::Shells;
  p.file = path;
  if (!off.packing.box) throw InputError(path, 1, "no '# box Lx Ly Lz' line: not a packing OFF (a packing OFF names its box after the OFF line)");
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
  for (std::size_t i = 0; i < off.comments.size(); ++i) {
    const auto& c = off.comments[i];
    if (c.rfind("D0=", 0) == 0 || c.rfind("d0=", 0) == 0) {
      p.d0 = parse_d0(c.substr(3), path, off.comment_lines[i]);
      p.d0_source = "file";
    }
  }
  p.comments = std::move(off.comments);
  p.comment_lines = std::move(off.comment_lines);
  if (p.d0_source.empty()) {
    const auto vols = shell_volumes(p.V, p.F, p.shell_offsets);
    double mean = 0;
    for (double v : vols) mean += v;
    mean /= static_cast<double>(vols.size());
    if (!(mean > 0)) throw InputError(path, 0, "shell volumes are not positive (faces oriented inward?); give --d0");
    p.d0 = std::cbrt(6 * mean / M_PI);
    p.d0_source = "shell_volume";
  }
  // A box of many millions of shell diameters is no packing, and what is built on it (cell
  // lists, voxel grids, CGAL's periodic Voronoi cells, which ran for minutes at 1e100 and
  // crashed at 1e308) has no use for it: said at the box line.
  for (int a = 0; a < 3; ++a)
    if (!(p.box[a] / p.d0 <= kMaxBoxInD0))
      throw InputError(path, off.packing.box_line,
                       fmt::format("box side {:g} is {:.3g} D0 (D0 = {:.4g}, from {}): more than {:g} D0, far beyond "
                                   "any packing", p.box[a], p.box[a] / p.d0, p.d0, p.d0_source, kMaxBoxInD0));
  return p;
}

Packing spheres_packing(io::SpherePackingFrame&& f, double scale) {
  Packing p;
  p.kind = Packing::Kind::Spheres;
  p.file = f.file;
  p.box = f.box;
  p.periodic = f.pbc;
  p.centres = std::move(f.centres);
  p.radii = std::move(f.radii);
  if (const auto d0 = f.positive_info("D0")) {
    p.d0 = *d0;
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

double max_scale(const Packing& p) {
  if (p.kind != Packing::Kind::Spheres || p.radii.size() == 0) return std::numeric_limits<double>::infinity();
  const double largest = p.radii.maxCoeff() / p.scale;
  return largest > 0 ? 0.5 * p.box.norm() / largest : std::numeric_limits<double>::infinity();
}

void check_scale(const Packing& p, double scale, const std::string& scale_text) {
  if (scale <= 1) return;  // the file's own spheres, or smaller ones
  const double bound = max_scale(p);
  if (scale <= bound) return;
  const double largest = p.radii.maxCoeff() / p.scale;
  throw UsageError(fmt::format("--scale {}: the largest sphere's radius would be {:.4g}, more than half the box's "
                               "diagonal {:.4g} (the sphere covers the whole box, and the work grows as the cube of "
                               "the scale): at most {:.4g} for {}",
                               scale_text, largest * scale, 0.5 * p.box.norm(), bound, p.file));
}

std::vector<Packing> read_packings(io::Input& input, const PackingReadOptions& options) {
  std::vector<Packing> packings;
  switch (input.format()) {
    case io::InputFormat::off:
      packings.push_back(read_shells(input));
      break;
    case io::InputFormat::xyz:
      for (auto& f : io::read_sphere_packing_xyz(input, io::PbcRule::as_in_file)) {
        packings.push_back(spheres_packing(std::move(f), 1.0));
        check_scale(packings.back(), options.scale, io::format_number(options.scale));
        packings.back().radii *= options.scale;
        packings.back().scale = options.scale;
      }
      break;
    default:
      input.fail_format("a packing: an OFF ('OFF' first) or an extended XYZ (an atom count first)");
  }
  if (options.d0 > 0)
    for (auto& p : packings) {
      p.d0 = options.d0;
      p.d0_source = "option";
    }
  return packings;
}

std::vector<Packing> read_packings(const std::string& path, const PackingReadOptions& options) {
  io::Input input(path);
  return read_packings(input, options);
}

Packing read_packing(const std::string& path, const PackingReadOptions& options) {
  auto packings = read_packings(path, options);
  return std::move(packings.back());
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
              // A shift by whole periods, not the minimum image of a separation: kept as
              // x -= L round(d / L) so the unwrapped coordinates stay bit-identical.
              const double d = V(w, a) - V(v, a);
              V(w, a) -= box[a] * std::nearbyint(d / box[a]);
            }
          todo.push(w);
        }
      }
    }
}

}  // namespace cmp::packing
