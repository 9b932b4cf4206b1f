#include "shell/compression.hpp"

#include "shell/observables.hpp"
#include "shell/shell_shapes.hpp"
#include "shell/wall_load.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <limits>

namespace cmp::shell {

namespace {
ShellSystem build(const ShellPacking& p, const CompressionOptions& o) {
  ShellModel m = o.model;
  m.shell_contacts = true;
  m.load.turgor = o.turgor0;
  m.contact.box = p.box;
  m.contact.box_periodic = p.periodic;
  m.walls = o.walls;
  m.contact.walls.clear();
  return make_shell_system(p.mesh, m);
}
}  // namespace

Compression::Compression(ShellPacking packing, CompressionOptions options)
    : packing_(std::move(packing)), options_(std::move(options)), system_(build(packing_, options_)), box_(packing_.box) {
  if (!system_.pressure() || !system_.contacts()) throw UsageError("compress: needs a pressure model and contacts");
  if (!(options_.step > 0)) throw UsageError("compress: the box step must be positive");
  if (options_.between_tolerance != 0 && !(options_.between_tolerance >= options_.relax.relative_tolerance))
    throw UsageError("compress: the tolerance between targets must be 0 (off) or at least the targets' tolerance");
  if (options_.walls && !(options_.phi_start > 0 && options_.phi_start < 1))
    throw UsageError("compress: the starting volume fraction of the walled box must lie in (0, 1)");
  relax_ = options_.relax;
  relax_.force_scale =
      default_force_scale(packing_.mesh, options_.model.material.youngs_modulus, options_.model.material.thickness);
  offsets_.push_back(0);
  for (int n : packing_.shell_vertex_counts) offsets_.push_back(offsets_.back() + n);
}

std::vector<std::string> Compression::term_names() const {
  std::vector<std::string> names;
  for (const auto& t : system_.terms()) names.push_back(t->name());
  return names;
}

double Compression::phi() const {
  double v = 0;
  for (double v0 : system_.pressure()->target_volumes()) v += v0;
  return v / (box_[0] * box_[1] * box_[2]);
}

void Compression::set_box(const Eigen::Vector3d& box) {
  box_ = box;
  system_.contacts()->set_box(box_, packing_.periodic);
  if (open_) system_.walls()->set_walls(box_walls(box_, packing_.periodic));
}

std::vector<Eigen::Vector3d> Compression::centroids() const {
  std::vector<Eigen::Vector3d> c;
  for (std::size_t k = 0; k + 1 < offsets_.size(); ++k) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) sum += system_.x.segment<3>(3 * v);
    c.push_back(sum / static_cast<double>(offsets_[k + 1] - offsets_[k]));
  }
  return c;
}

void Compression::open_box() {
  const double rv = options_.model.contact.vertex_radius;
  const auto c = centroids();
  const std::size_t n = c.size();
  // Each shell's extent about its centroid, widened by the vertex sphere and a gap of R_v.
  std::vector<Eigen::Vector3d> lo(n), hi(n);
  for (std::size_t k = 0; k < n; ++k) {
    lo[k] = hi[k] = Eigen::Vector3d::Zero();
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) {
      const Eigen::Vector3d d = system_.x.segment<3>(3 * v) - c[k];
      lo[k] = lo[k].cwiseMin(d);
      hi[k] = hi[k].cwiseMax(d);
    }
    lo[k].array() -= 2 * rv;
    hi[k].array() += 2 * rv;
  }
  // The enclosing box with the centroids times f; its phi falls as f grows.
  const auto bounds = [&](double f, Eigen::Vector3d& low, Eigen::Vector3d& high) {
    low.setConstant(std::numeric_limits<double>::infinity());
    high = -low;
    for (std::size_t k = 0; k < n; ++k) {
      low = low.cwiseMin(f * c[k] + lo[k]);
      high = high.cwiseMax(f * c[k] + hi[k]);
    }
  };
  double volume = 0;
  for (double v0 : system_.pressure()->target_volumes()) volume += v0;
  const auto phi_at = [&](double f) {
    Eigen::Vector3d low, high;
    bounds(f, low, high);
    return volume / (high - low).prod();
  };
  const double phi_enclosed = phi_at(1.0);
  if (!(options_.phi_start < phi_enclosed))
    throw UsageError("--phi-start " + std::to_string(options_.phi_start) +
                     " must lie below the volume fraction of the inflated jammed shells in the box enclosing them (" +
                     std::to_string(phi_enclosed) + "; phi_J = " + std::to_string(phi_jammed_) + ")");
  double a = 1.0, b = 2.0;
  while (phi_at(b) > options_.phi_start) b *= 2;
  for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
    const double m = 0.5 * (a + b);
    (phi_at(m) > options_.phi_start ? a : b) = m;
  }
  Eigen::Vector3d low, high;
  bounds(b, low, high);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d shift = (b - 1.0) * c[k] - low;
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) system_.x.segment<3>(3 * v) += shift;
  }
  packing_.periodic = {false, false, false};
  open_ = true;
  set_box(high - low);
}

double Compression::free_advance() const {
  // A shell reaches R_v beyond its vertices towards a wall, half the contact reach towards
  // another shell.
  const double rv = std::max(options_.model.contact.vertex_radius, 0.5 * system_.contacts()->contact_reach());
  const auto c = centroids();
  const std::size_t n = c.size();
  // Bounding spheres of the vertex spheres about each centroid.
  std::vector<double> rho(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v)
      rho[k] = std::max(rho[k], (system_.x.segment<3>(3 * v) - c[k]).norm());
    rho[k] += rv;
  }
  // Two rigidly swept shells approach each other by at most the box side's change; a shell
  // fits between two walls while the side exceeds its diameter.
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    gap = std::min(gap, box_.minCoeff() - 2.0 * rho[i]);
    for (std::size_t j = i + 1; j < n; ++j) gap = std::min(gap, (c[i] - c[j]).norm() - rho[i] - rho[j]);
  }
  return std::max(gap, 0.0);
}

void Compression::sweep(double s) {
  const double rv = options_.model.contact.vertex_radius;
  const Eigen::Vector3d advance = 0.5 * (1.0 - s) * box_;  // of each wall
  Eigen::VectorXd& x = system_.x;
  for (std::size_t k = 0; k + 1 < offsets_.size(); ++k) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) {
      low = low.cwiseMin(x.segment<3>(3 * v));
      high = high.cwiseMax(x.segment<3>(3 * v));
    }
    // The overlaps with the low and high walls before and after the walls move, in the frame
    // of the old box; the shell moves by the growth of its overlap (towards the centre).
    Eigen::Vector3d shift = -advance;  // the new frame: walls at 0 and s L
    for (int a = 0; a < 3; ++a) {
      const double lo_old = rv - low[a], hi_old = high[a] + rv - box_[a];
      shift[a] += (std::max(0.0, lo_old + advance[a]) - std::max(0.0, lo_old)) -
                  (std::max(0.0, hi_old + advance[a]) - std::max(0.0, hi_old));
    }
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) x.segment<3>(3 * v) += shift;
  }
  set_box(box_ * s);
}

void Compression::wrap_shells() {
  Eigen::VectorXd& x = system_.x;
  for (std::size_t s = 0; s + 1 < offsets_.size(); ++s) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v = offsets_[s]; v < offsets_[s + 1]; ++v) c += x.segment<3>(3 * v);
    c /= static_cast<double>(offsets_[s + 1] - offsets_[s]);
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    for (int a = 0; a < 3; ++a)
      if (packing_.periodic[a]) shift[a] = -box_[a] * std::floor(c[a] / box_[a]);
    if (shift.isZero()) continue;
    for (int v = offsets_[s]; v < offsets_[s + 1]; ++v) x.segment<3>(3 * v) += shift;
  }
}

CompressionRow Compression::start(const RelaxProgress& progress) {
  TurgorPressure* pressure = system_.pressure();
  pressure->set_turgor(options_.turgor0);
  // Inflation at the fixed turgor Pi_0: the constant-volume rule stays off until V0 is known.
  RelaxParameters inflate = relax_;
  inflate.max_volume_updates = 0;
  inflate.volume_tolerance = std::numeric_limits<double>::infinity();
  set_box(box_);
  const RelaxResult r = relax(system_, inflate, progress);
  pressure->set_target_volumes(pressure->volumes(span_of(system_.x)));
  wrap_shells();
  phi_jammed_ = phi();
  resolve_relative_targets();
  if (options_.walls) open_box();
  step_ = 0;
  next_target_ = 0;
  while (next_target_ < options_.targets.size() && options_.targets[next_target_] <= phi()) ++next_target_;
  CompressionRow row = observe();
  row.relax = r;
  return row;
}

CompressionRow Compression::advance(const RelaxProgress& progress) {
  if (done()) throw std::logic_error("compress: every target reached");
  const double target = options_.targets[next_target_];
  const double longest = box_.maxCoeff();
  const double by_step = 1.0 - options_.step / longest;
  const double to_target = std::cbrt(phi() / target);
  // Walls: while the shells' bounding spheres are apart, the rigid sweep is exact (no shell
  // meets another or both walls of an axis), so the step may be as large as their gaps allow.
  const double step_factor = open_ ? 1.0 - std::max(options_.step, free_advance()) / longest : by_step;
  const bool lands = to_target >= step_factor;
  const double s = lands ? to_target : step_factor;
  if (open_) {
    sweep(s);
  } else {
    // Affine: every shell moves rigidly with its vertex centroid.
    Eigen::VectorXd& x = system_.x;
    const auto c = centroids();
    for (std::size_t k = 0; k + 1 < offsets_.size(); ++k) {
      const Eigen::Vector3d shift = (s - 1.0) * c[k];
      for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) x.segment<3>(3 * v) += shift;
    }
    set_box(box_ * s);
  }
  RelaxResult r;
  RelaxParameters step_relax = relax_;
  if (!lands && options_.between_tolerance > 0) {
    step_relax.relative_tolerance = options_.between_tolerance;
    // Pi starts moving inside FIRE at the same residual as at a target (volume_update_factor
    // times the targets' tolerance), not that factor above the looser one: far from
    // equilibrium the volumes do not yet answer to Pi.
    step_relax.volume_update_factor = std::max(
        1.0, relax_.volume_update_factor * relax_.relative_tolerance / options_.between_tolerance);
  }
  try {
    r = relax(system_, step_relax, progress);
  } catch (const ComputationError& e) {
    throw ComputationError("step " + std::to_string(step_ + 1) + " (phi " + std::to_string(phi()) + "): " + e.what());
  }
  wrap_shells();
  ++step_;
  CompressionRow row = observe();
  row.relax = r;
  if (lands) {
    // The box was sized for the target: report it, not its rounding.
    row.phi = target;
    row.dphi = target - phi_jammed_;
    row.target = next_target_++;
  }
  return row;
}

CompressionRow Compression::observe() const {
  const Eigen::VectorXd& x = system_.x;
  const int n = static_cast<int>(offsets_.size()) - 1;
  CompressionRow row;
  row.step = step_;
  row.phi = phi();
  row.dphi = row.phi - phi_jammed_;
  row.box_side = box_.maxCoeff();
  // Shell centres (vertex centroids) for the molecular virial.
  const std::vector<Eigen::Vector3d> centre = centroids();
  const auto& shell_of = system_.contacts()->vertex_shells();
  // Contacts: touching shell pairs, each periodic image of the other shell its own contact (in
  // a small box a shell touches a neighbour and that neighbour's image: two contacts, as
  // `shellpack analyze` counts them); and the virial sum_contacts F_ij . (c_I - c_J), with the
  // centres' separation taken through the contact's own image: d - (x_i - c_I) + (q - c_J),
  // q the pushing point (a vertex, or the closest point of a triangle) in J's own frame.
  std::set<std::array<int, 5>> touching;  // I < J, J's image seen from I
  double virial = 0;
  for (const auto& c : system_.contacts()->touches(span_of(x))) {
    int I = shell_of[c.i], J = shell_of[c.corners[0]];
    Eigen::Vector3i k = touch_image(c, span_of(x), box_, packing_.periodic);
    if (I > J) std::swap(I, J), k = -k;
    touching.insert({I, J, k[0], k[1], k[2]});
    const Eigen::Vector3d R = c.d - (x.segment<3>(3 * c.i) - centre[shell_of[c.i]]) +
                              (touch_point(c, span_of(x)) - centre[shell_of[c.corners[0]]]);
    if (c.r > 0) virial += c.force * c.d.dot(R) / c.r;
  }
  row.contacts = static_cast<long>(touching.size());
  row.Z = 2.0 * static_cast<double>(row.contacts) / n;
  row.dZ = row.Z - (6.0 - 4.0 / n);
  row.pressure = virial / (3.0 * box_.prod()) / options_.model.material.youngs_modulus;
  // Turgor statistics.
  const auto& pi = system_.pressure()->turgors();
  double mean = 0, var = 0;
  for (double p : pi) mean += p;
  mean /= n;
  for (double p : pi) var += (p - mean) * (p - mean);
  var /= n;
  row.turgor_mean = mean / options_.turgor0;
  row.turgor_cv = mean != 0 ? std::sqrt(var) / std::abs(mean) : 0.0;
  // Shapes.
  const mesh::VertexMatrix vertices = Eigen::Map<const mesh::VertexMatrix>(x.data(), x.size() / 3, 3);
  for (const ShellShape& shape : shell_shapes(vertices, offsets_)) {  // shells are whole: no unwrapping
    row.asphericity += shape.asphericity;
    row.delta_eps += shape.aspect_deviation;
  }
  row.asphericity /= n;
  row.delta_eps /= n;
  row.volume_error = system_.pressure()->volume_error(span_of(x));
  if (open_) {
    const WallLoad load = wall_load(vertices, system_.rest().F, box_, packing_.periodic, options_.model.contact);
    row.wall_pressure = load.pressure() / options_.model.material.youngs_modulus;
    row.coverage = load.coverage();
  }
  row.term_energies = system_.term_energies(x);
  for (double e : row.term_energies) row.energy += e;
  const double unit = options_.model.material.youngs_modulus;
  row.energy /= unit;
  for (double& e : row.term_energies) e /= unit;
  return row;
}

CompressionState Compression::state() const {
  CompressionState s;
  s.step = step_;
  s.box = box_;
  s.next_target = next_target_;
  s.phi_jammed = phi_jammed_;
  s.x = system_.x;
  s.turgor = system_.pressure()->turgors();
  s.volume0 = system_.pressure()->target_volumes();
  return s;
}

void Compression::resolve_relative_targets() {
  if (!options_.targets_relative) return;
  if (relative_targets_.empty()) relative_targets_ = options_.targets;
  options_.targets.clear();
  for (double dphi : relative_targets_) {
    const double phi = std::round((phi_jammed_ + dphi) * 1e6) / 1e6;
    if (phi > 1)
      throw UsageError(fmt::format("--dphi: {} above phi_J = {} is a volume fraction above 1", dphi, phi_jammed_));
    if (options_.targets.empty() || phi > options_.targets.back()) options_.targets.push_back(phi);
  }
}

void Compression::restore(const CompressionState& s) {
  if (s.x.size() != system_.x.size() || s.turgor.size() != system_.pressure()->turgors().size() ||
      s.volume0.size() != s.turgor.size())
    throw std::invalid_argument("compress: a state of another packing");
  step_ = s.step;
  if (options_.walls) {
    packing_.periodic = {false, false, false};
    open_ = true;
  }
  // The next target is found in this run's list (a resume may name other targets; the state's
  // index counts in the list of the run that saved it).
  next_target_ = 0;
  phi_jammed_ = s.phi_jammed;
  resolve_relative_targets();
  system_.x = s.x;
  system_.pressure()->set_turgors(s.turgor);
  system_.pressure()->set_target_volumes(s.volume0);
  set_box(s.box);
  // A resume may name other targets: never one the state has already passed.
  while (next_target_ < options_.targets.size() && options_.targets[next_target_] <= phi() * (1.0 + 1e-9))
    ++next_target_;
}

}  // namespace cmp::shell
