#include "lbm/flow_solver.hpp"

#include "lbm/d3q19.hpp"
#include "lbm/layout.hpp"
#include "lbm/sweep_kernel.hpp"

#include "core/errors.hpp"
#include "core/fixed_chunks.hpp"
#include "core/thread_governor.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <istream>
#include <limits>
#include <ostream>

#include <sys/mman.h>

namespace cmp::lbm {

namespace {

constexpr char kMagic[8] = {'C', 'M', 'P', 'L', 'B', 'M', '1', '\n'};

// 64-bit FNV-1a.
struct Fnv {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

// An interpolated (Bouzidi) wall link, applied after each step:
// F[target] = k[0] F[target] + k[1] F[first[parity]] + k[2] F[second[parity]].
struct WallLink {
  std::uint32_t target;
  std::uint32_t first[2], second[2];  // [0]: after an even step, [1]: after an odd step
  double k[3];
};

// A fluid node on the inlet or outlet plane (Zou-He pressure node).
struct PressureNode {
  long node;
  int sign;    // +1: inlet (the inward normal is +axis), -1: outlet
  double rho;  // imposed density
};

// Allocator of the big arrays: 2 MB aligned and marked for transparent huge pages (the
// kernel's default is often "madvise"). The sweep touches ~10 pages per batch, whose TLB
// misses are expensive in a virtual machine (two-level page walks).
template <class T>
struct HugePages {
  using value_type = T;
  HugePages() = default;
  template <class U>
  HugePages(const HugePages<U>&) {}
  T* allocate(std::size_t n) {
    constexpr std::size_t kHuge = std::size_t{2} << 20;
    const std::size_t bytes = (n * sizeof(T) + kHuge - 1) / kHuge * kHuge;
    void* p = std::aligned_alloc(kHuge, bytes);
    if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }
  template <class U>
  bool operator==(const HugePages<U>&) const { return true; }
};

template <class T>
using BigVector = std::vector<T, HugePages<T>>;

}  // namespace

// Quadratic Bouzidi interpolation (when two fluid nodes lie behind the wall link): measured on
// the sphere array it overshoots more than the linear one (kappa +5 % vs +4 % at r = 5), so off.
constexpr bool kQuadratic = false;

struct FlowSolver::Impl {
  FlowSettings settings;
  int n[3] = {0, 0, 0};
  long fluid = 0, stride = 0, steps = 0;
  std::vector<long> site;              // fluid node -> grid index
  BigVector<std::uint32_t> links;     // 18 * (stride + padding)
  BigVector<double> fd;                // populations (double storage)
  BigVector<float> ff;                 // populations (float storage)
  std::vector<PressureNode> open;
  std::vector<WallLink> walls;
  long wall_links = 0;
  std::unique_ptr<CollisionOperator> op;
  double force[3] = {0, 0, 0};
  double nu = 0, grad_p = 0;
  int chunks = 1;
  std::uint64_t fp = 0;

  long chunk_start(int c) const { return chunk_begin(stride, chunks, c, kBatch); }

  template <class Real>
  BigVector<Real>& pops();

  template <class Real>
  void step_once();
  // Slot holding the population arriving at `node` along q for the next step, after a step of
  // parity `after_odd` (AA pattern: the slot moves with the parity).
  std::size_t incoming_slot(int q, long node, bool after_odd) const {
    if (q == 0) return pop_slot(0, node);
    return after_odd ? pop_slot(q, node) : links[link_index(opposite(q), node)];
  }
  template <class Real>
  void pressure_node(BigVector<Real>& F, const PressureNode& p, bool after_odd) const;
  template <class Real>
  void gather(const BigVector<Real>& F, long node, double f[kQ]) const;
  template <class Real>
  FlowObservables observe() const;
};

template <>
BigVector<double>& FlowSolver::Impl::pops<double>() { return fd; }
template <>
BigVector<float>& FlowSolver::Impl::pops<float>() { return ff; }

template <class Real>
void FlowSolver::Impl::step_once() {
  BigVector<Real>& F = pops<Real>();
  const bool odd = (steps & 1) != 0;
  const double* g = settings.driving == Driving::kBodyForce ? force : nullptr;
  for_each_chunk(chunks, [&](int c) {
    SweepRange<Real> r{F.data(), links.data(), chunk_start(c), chunk_start(c + 1), odd, g};
    op->sweep(r);
  });
  // Boundary passes: each node touches only its own slots. The pressure planes are cut into
  // fixed chunks over the threads (same bits for any thread count): in the bench's porous 128^3
  // box their ~11 000 nodes took 1.4 ms of a 15.5 ms step on one thread while the other
  // waited. The few interpolated wall links run in a fixed order.
  const long n_open = static_cast<long>(open.size());
  const int open_chunks = n_open >= 256 ? 8 : 1;
  for_each_chunk(open_chunks, [&](int c) {
    const long end = chunk_begin(n_open, open_chunks, c + 1);
    for (long i = chunk_begin(n_open, open_chunks, c); i < end; ++i) pressure_node(F, open[static_cast<std::size_t>(i)], odd);
  });
  const int parity = odd ? 1 : 0;
  for (const WallLink& w : walls)
    store_population(F.data(), w.target,
                     w.k[0] * load_population(F.data(), w.target) + w.k[1] * load_population(F.data(), w.first[parity]) +
                         w.k[2] * load_population(F.data(), w.second[parity]));
  ++steps;
}

// Zou & He (1997) pressure node, in the D3Q19 form of Hecht & Harting (2010): from the
// imposed density and the known populations (those not arriving from outside the box),
// the normal momentum j_n = rho_b - (sum_{c.n=0} f + 2 sum_{c.n=-1} f); each unknown
// population (c.n = +1) is its opposite plus the equilibrium difference, j_n/3 (face) or
// j_n/6 (edge), minus the transverse correction c_t N_t, N_t = 1/2 sum_{c.n=0} f c_t, that
// zeroes the tangential momentum (the pressure planes carry no tangential velocity).
template <class Real>
void FlowSolver::Impl::pressure_node(BigVector<Real>& F, const PressureNode& p, bool after_odd) const {
  const int a = settings.axis, b = (a + 1) % 3, c = (a + 2) % 3;
  double f[kQ];
  std::size_t slots[kQ];
  for (int q = 0; q < kQ; ++q) {
    slots[q] = incoming_slot(q, p.node, after_odd);
    f[q] = load_population(F.data(), slots[q]);
  }
  double level = 0, out = 0, nb = 0, nc = 0;
  for (int q = 0; q < kQ; ++q) {
    const int cn = velocity(q, a) * p.sign;
    if (cn == 0) {
      level += f[q];
      nb += 0.5 * velocity(q, b) * f[q];
      nc += 0.5 * velocity(q, c) * f[q];
    } else if (cn < 0) {
      out += f[q];
    }
  }
  const double jn = p.rho - (level + 2 * out);
  for (int q = 1; q < kQ; ++q) {
    if (velocity(q, a) * p.sign != 1) continue;
    const int cb = velocity(q, b), cc = velocity(q, c);
    const double v = cb == 0 && cc == 0 ? f[opposite(q)] + jn / 3 : f[opposite(q)] + jn / 6 - cb * nb - cc * nc;
    store_population(F.data(), slots[q], v);
  }
}

// Pre-collision populations of a node at the current step count.
template <class Real>
void FlowSolver::Impl::gather(const BigVector<Real>& F, long node, double f[kQ]) const {
  for (int q = 0; q < kQ; ++q) f[q] = load_population(F.data(), incoming_slot(q, node, (steps & 1) == 0));
}

template <class Real>
FlowObservables FlowSolver::Impl::observe() const {
  const BigVector<Real>& F = const_cast<Impl*>(this)->pops<Real>();
  const int a = settings.axis;
  struct Part {
    double ua = 0, speed = 0, mass = 0, max_speed = 0;
  };
  std::vector<Part> parts(static_cast<std::size_t>(chunks));
  const double half[3] = {0.5 * force[0], 0.5 * force[1], 0.5 * force[2]};
  for_each_chunk(chunks, [&](int c) {
    Part p;
    const long end = std::min(chunk_start(c + 1), fluid);
    for (long i = chunk_start(c); i < end; ++i) {
      double f[kQ];
      gather(F, i, f);
      double rho = 0, u[3] = {0, 0, 0};
      for (int q = 0; q < kQ; ++q) {
        rho += f[q];
        u[0] += kCx[q] * f[q];
        u[1] += kCy[q] * f[q];
        u[2] += kCz[q] * f[q];
      }
      for (int d = 0; d < 3; ++d) u[d] += half[d];
      const double s = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      p.ua += u[a];
      p.speed += s;
      p.mass += rho;
      p.max_speed = std::max(p.max_speed, s);
    }
    parts[static_cast<std::size_t>(c)] = p;
  });
  Part t;
  for (const Part& p : parts) {
    t.ua += p.ua;
    t.speed += p.speed;
    t.mass += p.mass;
    t.max_speed = std::max(t.max_speed, p.max_speed);
  }
  FlowObservables o;
  o.steps = steps;
  const double box = static_cast<double>(n[0]) * n[1] * n[2];
  o.superficial_velocity = t.ua / box;
  o.interstitial_velocity = t.ua / static_cast<double>(fluid);
  o.max_speed = t.max_speed;
  o.pressure_gradient = grad_p;
  o.kappa_lu = nu * o.superficial_velocity / grad_p;
  o.tortuosity = t.speed / t.ua;
  o.reynolds = o.superficial_velocity * std::sqrt(std::abs(o.kappa_lu)) / nu;
  o.mach = t.max_speed / std::sqrt(kCs2);
  o.mass = t.mass;
  return o;
}

FlowSolver::FlowSolver(const PoreLattice& lattice, const FlowSettings& settings) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.settings = settings;
  m.op = collision_style(settings.collision).make(settings.collision_parameters);
  const int a = settings.axis;
  if (a < 0 || a > 2) throw UsageError("flow axis must be 0, 1 or 2, got " + std::to_string(a));
  if (lattice.nx < 1 || lattice.ny < 1 || lattice.nz < 1 || lattice.fluid.size() != static_cast<std::size_t>(lattice.nodes()))
    throw UsageError("pore lattice: sizes do not match the fluid mask");
  m.n[0] = lattice.nx;
  m.n[1] = lattice.ny;
  m.n[2] = lattice.nz;
  const bool pressure = settings.driving == Driving::kPressure;
  if (pressure && !(std::isfinite(settings.density_drop) && std::abs(settings.density_drop) < 1.0))
    throw UsageError("density drop must be finite and below 1 in magnitude, got " + std::to_string(settings.density_drop));
  if (!pressure && !std::isfinite(settings.body_force))
    throw UsageError("body force must be finite, got " + std::to_string(settings.body_force));
  if (pressure && m.n[a] < 2) throw UsageError("pressure driving needs at least 2 planes along the flow axis");
  if (pressure && settings.density_drop == 0) throw UsageError("density drop must be non-zero");
  if (!pressure && settings.body_force == 0) throw UsageError("body force must be non-zero");
  const double tau = settings.collision_parameters.tau;
  m.nu = (tau - 0.5) * kCs2;
  m.grad_p = pressure ? kCs2 * settings.density_drop / (m.n[a] - 1) : settings.body_force;
  if (!pressure) m.force[a] = settings.body_force;

  // Number the fluid nodes slab by slab along the axis (axis coordinate slowest).
  const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;  // the other two axes, lower first (fastest)
  std::vector<long> node_of(static_cast<std::size_t>(lattice.nodes()), -1);
  for (int s = 0; s < m.n[a]; ++s)
    for (int v = 0; v < m.n[c]; ++v)
      for (int u = 0; u < m.n[b]; ++u) {
        int xyz[3];
        xyz[a] = s;
        xyz[b] = u;
        xyz[c] = v;
        const long i = lattice.index(xyz[0], xyz[1], xyz[2]);
        if (!lattice.fluid[static_cast<std::size_t>(i)]) continue;
        node_of[static_cast<std::size_t>(i)] = static_cast<long>(m.site.size());
        m.site.push_back(i);
      }
  m.fluid = static_cast<long>(m.site.size());
  if (m.fluid == 0) throw UsageError("pore lattice has no fluid node");
  m.stride = (m.fluid + kBatch - 1) / kBatch * kBatch;
  if (static_cast<double>(m.stride) * kQ >= 4294967295.0)
    throw UsageError("pore lattice too large: " + std::to_string(m.fluid) + " fluid nodes (at most 2^32/19)");
  m.chunks = static_cast<int>(std::clamp<long>(m.stride / (kBatch * 256), 1, 64));

  // Link table and boundary lists.
  const long N = m.stride;
  // kPrefetchAhead blocks of padding (slot 0) for the odd sweep's prefetches past the end.
  m.links.assign(static_cast<std::size_t>(18 * (N + kernel::kPrefetchAhead * kBatch)), 0);
  auto slot = [](int q, long node) { return static_cast<std::uint32_t>(pop_slot(q, node)); };
  const double rho_in = 1 + 0.5 * settings.density_drop, rho_out = 1 - 0.5 * settings.density_drop;
  struct Pending {
    long node;
    int q;
    double fraction;
  };
  std::vector<Pending> pending;
  for (long i = 0; i < N; ++i) {
    if (i >= m.fluid) {  // padding: an isolated node that bounces everything back
      for (int q = 1; q < kQ; ++q) m.links[link_index(q, i)] = slot(opposite(q), i);
      continue;
    }
    const long g = m.site[static_cast<std::size_t>(i)];
    const int x = static_cast<int>(g % m.n[0]), y = static_cast<int>(g / m.n[0] % m.n[1]),
              z = static_cast<int>(g / m.n[0] / m.n[1]);
    const int xyz[3] = {x, y, z};
    if (pressure && (xyz[a] == 0 || xyz[a] == m.n[a] - 1))
      m.open.push_back({i, xyz[a] == 0 ? 1 : -1, xyz[a] == 0 ? rho_in : rho_out});
    for (int q = 1; q < kQ; ++q) {
      int t[3] = {x + kCx[q], y + kCy[q], z + kCz[q]};
      bool outside = false;
      for (int d = 0; d < 3; ++d) {
        if (pressure && d == a && (t[d] < 0 || t[d] >= m.n[d])) outside = true;
        t[d] = (t[d] % m.n[d] + m.n[d]) % m.n[d];
      }
      std::uint32_t& link = m.links[link_index(q, i)];
      if (outside) {  // bounced back, then replaced by the pressure node pass
        link = slot(opposite(q), i);
        continue;
      }
      const long j = node_of[static_cast<std::size_t>(lattice.index(t[0], t[1], t[2]))];
      if (j >= 0) {
        link = slot(q, j);
      } else {
        link = slot(opposite(q), i);
        ++m.wall_links;
        if (lattice.wall_fraction) {
          const double fr = lattice.wall_fraction(x, y, z, q);
          if (!(fr > 0 && fr <= 1))
            throw UsageError("wall fraction must lie in (0, 1], got " + std::to_string(fr));
          if (fr != 0.5) pending.push_back({i, q, fr});
        }
      }
    }
  }
  // Interpolated links (Bouzidi, Firdaouss & Lallemand 2001, quadratic; linear when only one
  // fluid node lies behind, half-way when none): for the wall link (x, q), fraction d of the
  // link in fluid, y = x - c_q and z = x - 2 c_q, the population arriving at x along o = -q is
  //   d < 1/2:  d(1 + 2d) f*_q(x) + (1 - 4d^2) f*_q(y) - d(1 - 2d) f*_q(z)
  //   d >= 1/2: f*_q(x) / (d(2d + 1)) + (2d - 1)/d f*_o(x) - (2d - 1)/(2d + 1) f*_o(y)
  // (linear: 2d f*_q(x) + (1 - 2d) f*_q(y), and f*_q(x)/(2d) + (2d - 1)/(2d) f*_o(x)). After a
  // step every post-collision value sits in the slot of the population it became: f*_q(y) is
  // what arrives at x along q, f*_o(x) what arrives at y along o, and so on.
  auto behind = [&](long node, int q) -> long {  // the fluid node node - c_q, or -1
    const std::uint32_t s = m.links[link_index(opposite(q), node)];
    return s == slot(q, node) ? -1 : slot_node(s);
  };
  for (const Pending& p : pending) {
    const int q = p.q, o = opposite(q);
    const double d = p.fraction;
    const long y = behind(p.node, q);
    if (y < 0) continue;  // plain bounce-back
    const long z = kQuadratic ? behind(y, q) : -1;
    WallLink w{};
    w.target = slot(o, p.node);
    for (int par = 0; par < 2; ++par) {
      const bool after_odd = par == 1;
      if (d < 0.5) {
        w.first[par] = static_cast<std::uint32_t>(m.incoming_slot(q, p.node, after_odd));
        w.second[par] = z >= 0 ? static_cast<std::uint32_t>(m.incoming_slot(q, y, after_odd)) : w.target;
      } else {
        w.first[par] = static_cast<std::uint32_t>(m.incoming_slot(o, y, after_odd));
        w.second[par] = z >= 0 ? static_cast<std::uint32_t>(m.incoming_slot(o, z, after_odd)) : w.target;
      }
    }
    if (z >= 0 && d < 0.5) {
      w.k[0] = d * (1 + 2 * d);
      w.k[1] = 1 - 4 * d * d;
      w.k[2] = -d * (1 - 2 * d);
    } else if (z >= 0) {
      w.k[0] = 1 / (d * (2 * d + 1));
      w.k[1] = (2 * d - 1) / d;
      w.k[2] = -(2 * d - 1) / (2 * d + 1);
    } else if (d < 0.5) {
      w.k[0] = 2 * d;
      w.k[1] = 1 - 2 * d;
    } else {
      w.k[0] = 1 / (2 * d);
      w.k[1] = (2 * d - 1) / (2 * d);
    }
    m.walls.push_back(w);
  }

  // Start: rest, linear density between the pressure planes.
  auto init = [&](auto& F) {
    F.assign(static_cast<std::size_t>(kQ * N), 0);
    for (long i = 0; i < N; ++i) {
      double rho = 1;
      if (pressure && i < m.fluid) {
        const long g = m.site[static_cast<std::size_t>(i)];
        const int xyz[3] = {static_cast<int>(g % m.n[0]), static_cast<int>(g / m.n[0] % m.n[1]),
                            static_cast<int>(g / m.n[0] / m.n[1])};
        rho = rho_in - settings.density_drop * xyz[a] / (m.n[a] - 1);
      }
      for (int q = 0; q < kQ; ++q) store_population(F.data(), pop_slot(q, i), weight(q) * rho);
    }
  };
  if (settings.precision == Precision::kFloat) init(m.ff);
  else init(m.fd);

  // Fingerprint: lattice, wall data, settings.
  Fnv h;
  h.bytes("cmp-lbm-1", 9);
  h.value(m.n);
  for (std::uint8_t v : lattice.fluid) h.value(static_cast<std::uint8_t>(v != 0));
  for (const WallLink& w : m.walls) {
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
  m.fp = h.h;
}

FlowSolver::~FlowSolver() = default;
FlowSolver::FlowSolver(FlowSolver&&) noexcept = default;
FlowSolver& FlowSolver::operator=(FlowSolver&&) noexcept = default;

void FlowSolver::step(long n) {
  if (n <= 0) return;
  ThreadGovernor governor;
  for (long k = 0; k < n; ++k) {
    if (impl_->settings.precision == Precision::kFloat) impl_->step_once<float>();
    else impl_->step_once<double>();
    governor.tick();
  }
}

FlowObservables FlowSolver::observe() const {
  return impl_->settings.precision == Precision::kFloat ? impl_->observe<float>() : impl_->observe<double>();
}

long FlowSolver::steps() const { return impl_->steps; }
long FlowSolver::fluid_nodes() const { return impl_->fluid; }
long FlowSolver::interpolated_links() const { return static_cast<long>(impl_->walls.size()); }
const FlowSettings& FlowSolver::settings() const { return impl_->settings; }

double FlowSolver::bytes_per_fluid_node() const {
  const Impl& m = *impl_;
  const double pop = m.settings.precision == Precision::kFloat ? sizeof(float) : sizeof(double);
  const double total = static_cast<double>(m.stride) * (kQ * pop + 18 * sizeof(std::uint32_t)) +
                       m.site.size() * sizeof(long) + m.open.size() * sizeof(PressureNode) + m.walls.size() * sizeof(WallLink);
  return total / static_cast<double>(m.fluid);
}

std::vector<double> FlowSolver::velocity_field() const {
  const Impl& m = *impl_;
  std::vector<double> out(static_cast<std::size_t>(3L * m.n[0] * m.n[1] * m.n[2]), 0.0);
  for (long i = 0; i < m.fluid; ++i) {
    double f[kQ];
    if (m.settings.precision == Precision::kFloat) m.gather(m.ff, i, f);
    else m.gather(m.fd, i, f);
    double u[3] = {0, 0, 0};
    for (int q = 0; q < kQ; ++q) {
      u[0] += kCx[q] * f[q];
      u[1] += kCy[q] * f[q];
      u[2] += kCz[q] * f[q];
    }
    const std::size_t s = static_cast<std::size_t>(m.site[static_cast<std::size_t>(i)]);
    for (int d = 0; d < 3; ++d) out[3 * s + d] = u[d] + 0.5 * m.force[d];
  }
  return out;
}

std::vector<double> FlowSolver::density_field() const {
  const Impl& m = *impl_;
  std::vector<double> out(static_cast<std::size_t>(m.n[0]) * m.n[1] * m.n[2], 0.0);
  for (long i = 0; i < m.fluid; ++i) {
    double f[kQ];
    if (m.settings.precision == Precision::kFloat) m.gather(m.ff, i, f);
    else m.gather(m.fd, i, f);
    double rho = 0;
    for (int q = 0; q < kQ; ++q) rho += f[q];
    out[static_cast<std::size_t>(m.site[static_cast<std::size_t>(i)])] = rho;
  }
  return out;
}

std::uint64_t FlowSolver::fingerprint() const { return impl_->fp; }

namespace {

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
