// The solver's fingerprint and its checkpoint file (lbm/flow_solver.hpp): the complete state
// and the convergence checks made so far, resumable bit for bit.
#include "lbm/flow_solver_state.hpp"

#include "core/errors.hpp"
#include "core/fnv1a.hpp"

#include <algorithm>
#include <cstring>
#include <istream>
#include <ostream>

namespace cmp::lbm {

namespace {

constexpr char kMagic[8] = {'C', 'M', 'P', 'L', 'B', 'M', '1', '\n'};

using Fnv = Fnv1a;

void put(std::ostream& out, const void* p, std::size_t n) { out.write(static_cast<const char*>(p), static_cast<std::streamsize>(n)); }

template <class T>
void put_value(std::ostream& out, const T& v) {
  put(out, &v, sizeof v);
}

bool get(std::istream& in, void* p, std::size_t n) {
  in.read(static_cast<char*>(p), static_cast<std::streamsize>(n));
  return static_cast<std::size_t>(in.gcount()) == n;
}

constexpr int kObservableFields = 11;

void pack(const FlowObservables& o, double v[kObservableFields]) {
  const double a[kObservableFields] = {static_cast<double>(o.steps), o.kappa_lu, o.tortuosity, o.superficial_velocity,
                                       o.interstitial_velocity, o.max_speed, o.reynolds, o.mach, o.mass,
                                       o.pressure_gradient, 0.0};
  std::copy(a, a + kObservableFields, v);
}

FlowObservables unpack(const double v[kObservableFields]) {
  FlowObservables o;
  o.steps = static_cast<long>(v[0]);
  o.kappa_lu = v[1];
  o.tortuosity = v[2];
  o.superficial_velocity = v[3];
  o.interstitial_velocity = v[4];
  o.max_speed = v[5];
  o.reynolds = v[6];
  o.mach = v[7];
  o.mass = v[8];
  o.pressure_gradient = v[9];
  return o;
}

}  // namespace

// Lattice, wall data, settings.
std::uint64_t FlowSolver::Impl::fingerprint_of(const PoreLattice& lattice) const {
  const bool pressure = settings.driving == Driving::kPressure;
  Fnv h;
  h.bytes("cmp-lbm-2", 9);  // 2: brick node order (lbm/layout.hpp); older checkpoints do not resume
  h.value(n);
  for (std::uint8_t v : lattice.fluid) h.value(static_cast<std::uint8_t>(v != 0));
  for (const WallLink& w : walls) {
    h.value(w.target);
    h.value(w.k);
  }
  h.bytes(settings.collision.data(), settings.collision.size());
  h.value(settings.collision_parameters.tau);
  h.value(settings.collision_parameters.magic);
  h.value(settings.axis);
  h.value(static_cast<int>(settings.driving));
  h.value(pressure ? settings.density_drop : settings.body_force);
  h.value(static_cast<int>(settings.precision));
  if (settings.precision == Precision::kFloat) h.bytes("deviation", 9);  // float slots hold f - w (layout.hpp)
  return h.h;
}

std::uint64_t FlowSolver::fingerprint() const { return impl_->fp; }

// Checkpoint layout (native byte order, x86-64 little-endian): 8-byte magic "CMPLBM1\n",
// uint64 fingerprint, int64 steps, int64 stride, int32 bytes per population, the populations
// (19 * stride values), uint64 history count, then 11 doubles per history entry.
void FlowSolver::save(std::ostream& out, const std::vector<FlowObservables>& history) const {
  const Impl& m = *impl_;
  put(out, kMagic, sizeof kMagic);
  put_value(out, m.fp);
  put_value(out, static_cast<std::int64_t>(m.steps));
  put_value(out, static_cast<std::int64_t>(m.stride));
  const bool f32 = m.settings.precision == Precision::kFloat;
  put_value(out, static_cast<std::int32_t>(f32 ? 4 : 8));
  if (f32) put(out, m.ff.data(), m.ff.size() * sizeof(float));
  else put(out, m.fd.data(), m.fd.size() * sizeof(double));
  put_value(out, static_cast<std::uint64_t>(history.size()));
  for (const FlowObservables& o : history) {
    double v[kObservableFields];
    pack(o, v);
    put(out, v, sizeof v);
  }
}

std::vector<FlowObservables> FlowSolver::load(std::istream& in, const std::string& name) {
  Impl& m = *impl_;
  char magic[8];
  if (!get(in, magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0)
    throw InputError(name, 0, "not a lattice Boltzmann checkpoint");
  std::uint64_t fp = 0;
  std::int64_t steps = 0, stride = 0;
  std::int32_t width = 0;
  if (!get(in, &fp, sizeof fp) || !get(in, &steps, sizeof steps) || !get(in, &stride, sizeof stride) ||
      !get(in, &width, sizeof width))
    throw InputError(name, 0, "truncated checkpoint");
  if (fp != m.fp)
    throw InputError(name, 0, "checkpoint is from another run (different lattice or settings)");
  const bool f32 = m.settings.precision == Precision::kFloat;
  if (stride != m.stride || width != (f32 ? 4 : 8) || steps < 0) throw InputError(name, 0, "checkpoint does not match the lattice");
  BigVector<double> fd;
  BigVector<float> ff;
  bool ok;
  if (f32) {
    ff.resize(m.ff.size());
    ok = get(in, ff.data(), ff.size() * sizeof(float));
  } else {
    fd.resize(m.fd.size());
    ok = get(in, fd.data(), fd.size() * sizeof(double));
  }
  std::uint64_t count = 0;
  if (!ok || !get(in, &count, sizeof count) || count > (1u << 30)) throw InputError(name, 0, "truncated checkpoint");
  std::vector<FlowObservables> history;
  for (std::uint64_t k = 0; k < count; ++k) {
    double v[kObservableFields];
    if (!get(in, v, sizeof v)) throw InputError(name, 0, "truncated checkpoint");
    history.push_back(unpack(v));
  }
  if (f32) m.ff = std::move(ff);
  else m.fd = std::move(fd);
  m.steps = steps;
  return history;
}

}  // namespace cmp::lbm
