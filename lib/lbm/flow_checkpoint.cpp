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

// 2: the populations node by node in the whole lattice's order (any rank count writes and
// reads the same file); 1 held the one process's arrays as they lay in memory.
constexpr char kMagic[8] = {'C', 'M', 'P', 'L', 'B', 'M', '2', '\n'};
constexpr char kMagicBefore[8] = {'C', 'M', 'P', 'L', 'B', 'M', '1', '\n'};
constexpr int kTagState = 201;
constexpr long kPieceNodes = 1 << 20;  // nodes per message on the way to rank 0

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
  // The wall links of every rank in the whole lattice's order (own node i is node first_node + i).
  std::vector<char> mine;
  for (const WallLink& w : walls) {
    const auto target = static_cast<std::uint32_t>(pop_slot(slot_direction(w.target), first_node + slot_node(w.target)));
    const char* t = reinterpret_cast<const char*>(&target);
    const char* k = reinterpret_cast<const char*>(&w.k);
    mine.insert(mine.end(), t, t + sizeof target);
    mine.insert(mine.end(), k, k + sizeof w.k);
  }
  const std::vector<char> all = comm.all_gather_bytes(mine);
  h.bytes(all.data(), all.size());
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

namespace {

// This rank's populations, node by node (19 slots each, as they lie at the current parity).
template <class Real>
void pack_nodes(const BigVector<Real>& F, long begin, long end, std::vector<Real>& out) {
  out.resize(static_cast<std::size_t>((end - begin) * kQ));
  for (long i = begin; i < end; ++i)
    for (int q = 0; q < kQ; ++q) out[static_cast<std::size_t>((i - begin) * kQ + q)] = F[pop_slot(q, i)];
}

// Rank 0 writes its nodes, then every other rank's, received piece by piece in rank order.
template <class Real>
void write_populations(std::ostream& out, const Communicator& comm, long fluid, const BigVector<Real>& F) {
  std::vector<Real> piece;
  const long pieces = (fluid + kPieceNodes - 1) / kPieceNodes;
  if (!comm.root()) {
    comm.send(0, kTagState, &pieces, sizeof pieces);
    comm.send(0, kTagState, &fluid, sizeof fluid);
    for (long k = 0; k < pieces; ++k) {
      pack_nodes(F, k * kPieceNodes, std::min(fluid, (k + 1) * kPieceNodes), piece);
      comm.send(0, kTagState, piece.data(), piece.size() * sizeof(Real));
    }
    return;
  }
  for (long k = 0; k < pieces; ++k) {
    pack_nodes(F, k * kPieceNodes, std::min(fluid, (k + 1) * kPieceNodes), piece);
    put(out, piece.data(), piece.size() * sizeof(Real));
  }
  for (int r = 1; r < comm.size(); ++r) {
    long n = 0;
    comm.recv(r, kTagState, &n, sizeof n);
    long left = 0;  // the rank's nodes: whole pieces but the last
    comm.recv(r, kTagState, &left, sizeof left);
    for (long k = 0; k < n; ++k) {
      const long count = std::min(left, kPieceNodes);
      piece.resize(static_cast<std::size_t>(count * kQ));
      comm.recv(r, kTagState, piece.data(), piece.size() * sizeof(Real));
      put(out, piece.data(), piece.size() * sizeof(Real));
      left -= count;
    }
  }
}

}  // namespace

// Checkpoint layout (native byte order, x86-64 little-endian): 8-byte magic "CMPLBM2\n",
// uint64 fingerprint, int64 steps, int64 fluid nodes, int32 bytes per population, the
// populations (19 values per fluid node, the nodes in the whole lattice's order, the values
// as the node's 19 slots hold them), uint64 history count, then 11 doubles per history entry.
// On several ranks rank 0 writes it all (the others send it their nodes); every rank reads
// its own nodes back, so a run saved on k ranks resumes on any number.
void FlowSolver::save(std::ostream& out, const std::vector<FlowObservables>& history) const {
  const Impl& m = *impl_;
  const bool f32 = m.settings.precision == Precision::kFloat;
  if (m.comm.root()) {
    put(out, kMagic, sizeof kMagic);
    put_value(out, m.fp);
    put_value(out, static_cast<std::int64_t>(m.steps));
    put_value(out, static_cast<std::int64_t>(m.global_fluid));
    put_value(out, static_cast<std::int32_t>(f32 ? 4 : 8));
  }
  if (f32) write_populations(out, m.comm, m.fluid, m.ff);
  else write_populations(out, m.comm, m.fluid, m.fd);
  if (!m.comm.root()) return;
  put_value(out, static_cast<std::uint64_t>(history.size()));
  for (const FlowObservables& o : history) {
    double v[kObservableFields];
    pack(o, v);
    put(out, v, sizeof v);
  }
}

namespace {
// Past `bytes` of the stream: a seek (each rank reads only its own nodes of a file every rank
// opens), a read where the stream cannot seek. A seek past the end shows as the next read failing.
bool skip_bytes(std::istream& in, long bytes) {
  if (in.seekg(bytes, std::ios::cur)) return true;
  in.clear();
  in.ignore(bytes);
  return in.gcount() == bytes;
}
}  // namespace

std::vector<FlowObservables> FlowSolver::load(std::istream& in, const std::string& name) {
  Impl& m = *impl_;
  std::vector<FlowObservables> history;
  const bool f32 = m.settings.precision == Precision::kFloat;
  // Read and checked on every rank (a rank that cannot hold its nodes, a truncated file: every
  // rank stops with one message); the collective halo fill comes after, outside agree.
  m.comm.agree([&] {
    char magic[8];
    if (!get(in, magic, sizeof magic)) throw InputError(name, 0, "not a lattice Boltzmann checkpoint");
    if (std::memcmp(magic, kMagicBefore, sizeof magic) == 0)
      throw InputError(name, 0, "checkpoint written by an older lbflow (version 1 state, before MPI): run it again from the start");
    if (std::memcmp(magic, kMagic, sizeof magic) != 0) throw InputError(name, 0, "not a lattice Boltzmann checkpoint");
    std::uint64_t fp = 0;
    std::int64_t steps = 0, nodes = 0;
    std::int32_t width = 0;
    if (!get(in, &fp, sizeof fp) || !get(in, &steps, sizeof steps) || !get(in, &nodes, sizeof nodes) ||
        !get(in, &width, sizeof width))
      throw InputError(name, 0, "truncated checkpoint");
    if (fp != m.fp)
      throw InputError(name, 0, "checkpoint is from another run (different lattice or settings)");
    if (nodes != m.global_fluid || width != (f32 ? 4 : 8) || steps < 0) throw InputError(name, 0, "checkpoint does not match the lattice");
    const long node_bytes = kQ * static_cast<long>(width);
    std::vector<char> mine(static_cast<std::size_t>(m.fluid * node_bytes));
    bool ok = skip_bytes(in, m.first_node * node_bytes) && get(in, mine.data(), mine.size()) &&
              skip_bytes(in, (m.global_fluid - m.first_node - m.fluid) * node_bytes);
    std::uint64_t count = 0;
    if (!ok || !get(in, &count, sizeof count) || count > (1u << 30)) throw InputError(name, 0, "truncated checkpoint");
    for (std::uint64_t k = 0; k < count; ++k) {
      double v[kObservableFields];
      if (!get(in, v, sizeof v)) throw InputError(name, 0, "truncated checkpoint");
      history.push_back(unpack(v));
    }
    const auto unpack_nodes = [&](auto& F) {
      using Real = std::remove_reference_t<decltype(F[0])>;
      const Real* v = reinterpret_cast<const Real*>(mine.data());
      for (long i = 0; i < m.fluid; ++i)
        for (int q = 0; q < kQ; ++q) F[pop_slot(q, i)] = v[i * kQ + q];
    };
    if (f32) unpack_nodes(m.ff);
    else unpack_nodes(m.fd);
    m.steps = steps;
  });
  // An odd step comes next: it gathers from the ghost slots, filled after every even step.
  if (m.steps & 1) {
    if (f32) m.halo.fill_ghosts(m.ff.data());
    else m.halo.fill_ghosts(m.fd.data());
  }
  return history;
}

}  // namespace cmp::lbm
