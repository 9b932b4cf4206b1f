#include "shell/hertz_contacts.hpp"

#include "shell/shell_partition.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"
#include "neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::shell {

void check_face_indices(const mesh::TriMesh& rest, const char* style) {
  for (Eigen::Index f = 0; f < rest.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (rest.F(f, k) < 0 || rest.F(f, k) >= rest.V.rows())
        throw UsageError(std::string(style) + ": face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(rest.F(f, k)) + " of a mesh with " + std::to_string(rest.V.rows()) +
                         " vertices");
}

neighbours::Box contact_box(const mesh::VertexMatrix& X, double cutoff,
                            const std::optional<ShellContactTerm::BoxSides>& sides, const char* style) {
  neighbours::Box box;
  box.lower = X.colwise().minCoeff().transpose().array() - cutoff;
  box.lengths = (X.colwise().maxCoeff().transpose() - box.lower).array() + cutoff;
  if (!box.lower.allFinite() || !box.lengths.allFinite())
    throw ComputationError(std::string(style) + ": a vertex position is not finite");
  if (sides)
    for (int a = 0; a < 3; ++a)
      if (sides->periodic[a]) {
        box.lower[a] = 0;
        box.lengths[a] = sides->lengths[a];
        box.periodic[a] = true;
      }
  return box;
}

neighbours::CellGrid contact_grid(const mesh::VertexMatrix& X, double cutoff,
                                  const std::optional<ShellContactTerm::BoxSides>& sides, const char* style) {
  const neighbours::Box box = contact_box(X, cutoff, sides, style);
  Eigen::Vector3i cells = Eigen::Vector3i::Zero();
  if (sides) {
    // The periodic axes span [0, L) (the grid wraps the points into it). Vertices lie on
    // surfaces, so the finest grid (cells one cutoff wide) would be mostly empty cells: about
    // one cell per vertex is enough and visits far fewer cells.
    const Eigen::Vector3i most = neighbours::CellGrid(box, cutoff).cells_per_axis();
    const int target = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(X.rows()))));
    for (int a = 0; a < 3; ++a) cells[a] = std::min(most[a], target);
  }
  neighbours::CellGrid grid(box, cutoff, cells);
  grid.build(X);
  return grid;
}

VertexContacts::VertexContacts(const mesh::TriMesh& rest, const ContactParameters& p)
    : radius_(p.vertex_radius), estar_(p.vertex_effective_modulus()) {
  validate(p, "hertz-vertices");
  check_face_indices(rest, "hertz-vertices");
  shell_of_ = shell_partition(rest.F, static_cast<int>(rest.V.rows())).vertex_shell;
  if (p.box) set_box(*p.box, p.box_periodic);
}

void VertexContacts::build_pair_list(std::span<const double> x) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  scratch_.resize(n, 3);
  std::copy(x.begin(), x.end(), scratch_.data());
  const double reach = (2.0 + kSkin) * radius_;
  const neighbours::CellGrid grid = contact_grid(scratch_, reach, box_, "hertz-vertices");
  pairs_.clear();
  grid.for_each_pair(scratch_, [&](int i, int j, const Eigen::Vector3d&, double) {
    if (shell_of_[i] != shell_of_[j]) pairs_.push_back({i, j});
  });
  reference_.assign(x.begin(), x.end());
  list_valid_ = true;
}

bool VertexContacts::pair_list_holds(std::span<const double> x) const {
  if (!list_valid_ || reference_.size() != x.size()) return false;
  const double limit2 = 0.25 * kSkin * kSkin * radius_ * radius_;  // half the skin, squared
  for (std::size_t k = 0; k < x.size(); k += 3) {
    const double dx = x[k] - reference_[k], dy = x[k + 1] - reference_[k + 1], dz = x[k + 2] - reference_[k + 2];
    if (!(dx * dx + dy * dy + dz * dz < limit2)) return false;
  }
  return true;
}

template <class Fn>
void VertexContacts::for_each_contact(std::span<const double> x, Fn&& f) const {
  const Eigen::Index n = static_cast<Eigen::Index>(shell_of_.size());
  if (n == 0) return;
  const double cutoff = 2.0 * radius_;
  if (box_) {
    // A Verlet list: every pair of different shells within 2 R_v (1 + skin/2) when built,
    // kept while no vertex has moved half the skin (then no pair outside it can be in
    // range). It is rebuilt after set_box(), so a run resumed at a box step builds the same
    // lists as one never stopped.
    if (!pair_list_holds(x)) build_pair_list(x);
    const double* X = x.data();
    double period[3], inverse[3];
    for (int a = 0; a < 3; ++a) {
      period[a] = box_->periodic[a] ? box_->lengths[a] : 0.0;
      inverse[a] = box_->periodic[a] ? 1.0 / box_->lengths[a] : 0.0;
    }
    const double cutoff2 = cutoff * cutoff;
    for (const auto& [i, j] : pairs_) {
      Eigen::Vector3d d;
      for (int a = 0; a < 3; ++a) d[a] = minimum_image(X[3 * i + a] - X[3 * j + a], period[a], inverse[a]);
      const double r2 = d.squaredNorm();
      if (r2 < cutoff2) f(i, j, d, std::sqrt(r2));
    }
    return;
  }
  scratch_.resize(n, 3);
  std::copy(x.begin(), x.end(), scratch_.data());
  const neighbours::CellGrid grid = contact_grid(scratch_, cutoff, box_, "hertz-vertices");
  grid.for_each_pair(scratch_, [&](int i, int j, const Eigen::Vector3d& d, double r2) {
    if (shell_of_[i] == shell_of_[j]) return;
    f(i, j, d, std::sqrt(r2));
  });
}

double VertexContacts::energy(std::span<const double> x) const {
  check_sizes(x);
  double sum = 0;
  for_each_contact(x, [&](int, int, const Eigen::Vector3d&, double r) {
    sum += hertz_energy(hertz_prefactor(estar_, 0.5 * radius_), 2.0 * radius_ - r);
  });
  return sum;
}

void VertexContacts::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  double* G = g.data();
  for_each_contact(x, [&](int i, int j, const Eigen::Vector3d& d, double r) {
    // dU/dx_i = -U'(h) d/r with d = x_i - x_j.
    const double s = -hertz_force(hertz_prefactor(estar_, 0.5 * radius_), 2.0 * radius_ - r) / r;
    for (int a = 0; a < 3; ++a) {
      G[3 * i + a] += s * d[a];
      G[3 * j + a] -= s * d[a];
    }
  });
}

void VertexContacts::set_box(const Eigen::Vector3d& lengths, std::array<bool, 3> periodic) {
  for (int a = 0; a < 3; ++a) {
    if (!(lengths[a] > 0) || !std::isfinite(lengths[a]))
      throw UsageError("hertz-vertices: box side " + std::to_string(lengths[a]) + " is not positive and finite");
    if (periodic[a] && !(lengths[a] >= 2.0 * (2.0 + kSkin) * radius_))
      throw UsageError("hertz-vertices: the periodic box side " + std::to_string(lengths[a]) +
                       " is shorter than " + std::to_string(2.0 * (2.0 + kSkin)) + " vertex radii (" +
                       std::to_string(2.0 * (2.0 + kSkin) * radius_) + ")");
  }
  box_ = BoxSides{lengths, periodic};
  list_valid_ = false;
}

std::vector<ShellContactTerm::Touch> VertexContacts::touches(std::span<const double> x) const {
  check_sizes(x);
  std::vector<Touch> out;
  for_each_contact(x, [&](int i, int j, const Eigen::Vector3d& d, double r) {
    const double h = 2.0 * radius_ - r;
    out.push_back({i, {j, -1, -1}, Eigen::Vector3d::UnitX(), d, r, h, hertz_force(hertz_prefactor(estar_, 0.5 * radius_), h)});
  });
  return out;
}

std::vector<char> VertexContacts::touching(std::span<const double> x) const {
  check_sizes(x);
  std::vector<char> t(shell_of_.size(), 0);
  for_each_contact(x, [&](int i, int j, const Eigen::Vector3d&, double) { t[i] = t[j] = 1; });
  return t;
}

WallContacts::WallContacts(const mesh::TriMesh& rest, const ContactParameters& p)
    : vertex_count_(rest.V.rows()), radius_(p.vertex_radius), estar_(p.wall_effective_modulus()), walls_(p.walls) {
  validate(p, "hertz-walls");
}

void WallContacts::set_walls(std::vector<Plane> walls) {
  ContactParameters p;
  p.walls = walls;
  validate(p, "hertz-walls");
  walls_ = std::move(walls);
}

double WallContacts::energy(std::span<const double> x) const {
  check_sizes(x);
  const double* X = x.data();
  double sum = 0;
  for (const Plane& w : walls_)
    for (long i = 0; i < vertex_count_; ++i) sum += hertz_energy(hertz_prefactor(estar_, radius_), radius_ - w.distance(X + 3 * i));
  return sum;
}

void WallContacts::add_gradient(std::span<const double> x, std::span<double> g) const {
  check_sizes(x, g);
  const double* X = x.data();
  double* G = g.data();
  for (const Plane& w : walls_)
    for (long i = 0; i < vertex_count_; ++i) {
      const double f = hertz_force(hertz_prefactor(estar_, radius_), radius_ - w.distance(X + 3 * i));
      if (f == 0) continue;
      for (int a = 0; a < 3; ++a) G[3 * i + a] -= f * w.normal[a];  // dh/dx = -normal
    }
}

std::vector<double> WallContacts::wall_forces(std::span<const double> x) const {
  check_sizes(x);
  const double* X = x.data();
  std::vector<double> out;
  for (const Plane& w : walls_) {
    double sum = 0;
    for (long i = 0; i < vertex_count_; ++i) sum += hertz_force(hertz_prefactor(estar_, radius_), radius_ - w.distance(X + 3 * i));
    out.push_back(sum);
  }
  return out;
}

std::vector<char> WallContacts::touching(std::span<const double> x) const {
  check_sizes(x);
  const double* X = x.data();
  std::vector<char> t(static_cast<std::size_t>(vertex_count_), 0);
  for (const Plane& w : walls_)
    for (long i = 0; i < vertex_count_; ++i)
      if (w.distance(X + 3 * i) < radius_) t[i] = 1;
  return t;
}

}  // namespace cmp::shell
