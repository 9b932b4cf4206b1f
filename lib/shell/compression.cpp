#include "shell/compression.hpp"

#include "shell/observables.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

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
  return make_shell_system(p.mesh, m);
}
}  // namespace

Compression::Compression(ShellPacking packing, CompressionOptions options)
    : packing_(std::move(packing)), options_(std::move(options)), system_(build(packing_, options_)), box_(packing_.box) {
  if (!system_.pressure() || !system_.contacts()) throw UsageError("compress: needs a pressure model and contacts");
  if (!(options_.step > 0)) throw UsageError("compress: the box step must be positive");
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
  step_ = 0;
  next_target_ = 0;
  while (next_target_ < options_.targets.size() && options_.targets[next_target_] <= phi_jammed_) ++next_target_;
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
  const bool lands = to_target >= by_step;
  const double s = lands ? to_target : by_step;
  // Affine: every shell moves rigidly with its vertex centroid.
  Eigen::VectorXd& x = system_.x;
  for (std::size_t k = 0; k + 1 < offsets_.size(); ++k) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) c += x.segment<3>(3 * v);
    c /= static_cast<double>(offsets_[k + 1] - offsets_[k]);
    const Eigen::Vector3d shift = (s - 1.0) * c;
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) x.segment<3>(3 * v) += shift;
  }
  set_box(box_ * s);
  RelaxResult r;
  try {
    r = relax(system_, relax_, progress);
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
  std::vector<Eigen::Vector3d> centre(n, Eigen::Vector3d::Zero());
  const auto& shell_of = system_.contacts()->vertex_shells();
  for (int k = 0; k < n; ++k) {
    for (int v = offsets_[k]; v < offsets_[k + 1]; ++v) centre[k] += x.segment<3>(3 * v);
    centre[k] /= static_cast<double>(offsets_[k + 1] - offsets_[k]);
  }
  // Contacts: touching shell pairs, and the virial sum_contacts F_ij . (c_I - c_J), with the
  // centres' separation taken through the contact's own image: d_ij - (x_i - c_I) + (x_j - c_J).
  std::vector<char> touch(static_cast<std::size_t>(n) * n, 0);
  double virial = 0;
  for (const auto& c : system_.contacts()->contacts(span_of(x))) {
    const int I = shell_of[c.i], J = shell_of[c.j];
    touch[static_cast<std::size_t>(I) * n + J] = touch[static_cast<std::size_t>(J) * n + I] = 1;
    const Eigen::Vector3d R = c.d - (x.segment<3>(3 * c.i) - centre[I]) + (x.segment<3>(3 * c.j) - centre[J]);
    virial += c.force * c.d.dot(R) / c.r;
  }
  for (int I = 0; I < n; ++I)
    for (int J = I + 1; J < n; ++J) row.contacts += touch[static_cast<std::size_t>(I) * n + J];
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
  for (int k = 0; k < n; ++k) {
    const auto g = gyration_eigenvalues(x.segment(3 * offsets_[k], 3 * (offsets_[k + 1] - offsets_[k])));
    row.asphericity += g[0] - 0.5 * (g[1] + g[2]);
    row.delta_eps += std::sqrt(g[0] / g[2]) - 1.0;
  }
  row.asphericity /= n;
  row.delta_eps /= n;
  row.volume_error = system_.pressure()->volume_error(span_of(x));
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
  next_target_ = s.next_target;
  phi_jammed_ = s.phi_jammed;
  resolve_relative_targets();
  system_.x = s.x;
  system_.pressure()->set_turgors(s.turgor);
  system_.pressure()->set_target_volumes(s.volume0);
  set_box(s.box);
}

}  // namespace cmp::shell
