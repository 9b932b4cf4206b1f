// FlowSolver's construction (settings checks, the build steps in order, the initial state) and
// its accessors; the parts live in the files listed in lbm/flow_solver_state.hpp.
#include "lbm/flow_solver_state.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <string>

namespace cmp::lbm {

FlowSolver::FlowSolver(const PoreLattice& lattice, const FlowSettings& settings)
    : FlowSolver(lattice, settings, Communicator()) {}

FlowSolver::FlowSolver(const PoreLattice& lattice, const FlowSettings& settings, const Communicator& comm)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.settings = settings;
  m.comm = comm;
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

  // Everything a rank holds, allocated before the first collective call: a rank that cannot
  // allocate its share stops every rank with one message (Communicator::agree).
  comm.agree([&] {
    const std::vector<WallFraction> fractions = m.build_link_table(lattice);
    m.build_walls(fractions);
    // Start: rest, linear density between the pressure planes.
    m.fill_equilibrium([&](long g, double& rho, double u[3]) {
      u[0] = u[1] = u[2] = 0;
      rho = m.rest_density(g);
    });
  });
  m.halo.build(m.comm, std::move(m.pending_ghosts), m.own_slot);  // m.comm: comm may be a temporary
  m.pending_ghosts = {};
  m.own_slot = nullptr;
  m.fp = m.fingerprint_of(lattice);
}

double FlowSolver::Impl::rest_density(long g) const {
  if (settings.driving != Driving::kPressure) return 1;
  const int a = settings.axis;
  const long xyz[3] = {g % n[0], g / n[0] % n[1], g / n[0] / n[1]};
  return 1 + 0.5 * settings.density_drop - settings.density_drop * static_cast<double>(xyz[a]) / (n[a] - 1);
}

// Every slot of this rank, ghost nodes too (for tidiness: the halo overwrites the slots that
// matter), set to the incompressible equilibrium of the state at its node's grid index.
void FlowSolver::Impl::fill_equilibrium(const StartState& state) {
  const long N = ghost_end;
  auto init = [&](auto& F) {
    F.assign(static_cast<std::size_t>(kQ * N), 0);
    for (long i = 0; i < N; ++i) {
      const long ghost = i - stride;
      const long g = i < fluid ? site[static_cast<std::size_t>(i)]
                     : ghost >= 0 && ghost < static_cast<long>(ghost_site.size()) ? ghost_site[static_cast<std::size_t>(ghost)]
                                                                                      : -1;
      double rho = 1, u[3] = {0, 0, 0};
      if (g >= 0) state(g, rho, u);
      const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
      for (int q = 0; q < kQ; ++q) {
        const double cu = kCx[q] * u[0] + kCy[q] * u[1] + kCz[q] * u[2];
        store_population(F.data(), pop_slot(q, i), weight(q) * (rho + 3 * cu + 4.5 * cu * cu - 1.5 * uu));
      }
    }
  };
  if (settings.precision == Precision::kFloat) init(ff);
  else init(fd);
}

void FlowSolver::start_from(const StartState& state) {
  Impl& m = *impl_;
  m.fill_equilibrium(state);
  m.steps = 0;
}

FlowSolver::~FlowSolver() = default;
FlowSolver::FlowSolver(FlowSolver&&) noexcept = default;
FlowSolver& FlowSolver::operator=(FlowSolver&&) noexcept = default;

long FlowSolver::steps() const { return impl_->steps; }
long FlowSolver::fluid_nodes() const { return impl_->global_fluid; }
long FlowSolver::interpolated_links() const { return impl_->comm.sum(static_cast<long>(impl_->walls.size())); }
double FlowSolver::halo_slots_per_step() const { return impl_->halo.slots_per_step(); }
double FlowSolver::halo_seconds() const { return impl_->halo_seconds; }
const FlowSettings& FlowSolver::settings() const { return impl_->settings; }

double FlowSolver::bytes_per_fluid_node() const {
  const Impl& m = *impl_;
  const double pop = m.settings.precision == Precision::kFloat ? sizeof(float) : sizeof(double);
  const double total = static_cast<double>(m.ghost_end) * (kQ * pop + 18 * sizeof(std::uint32_t)) +
                       m.consecutive.size() * sizeof(std::uint32_t) + m.site.size() * sizeof(long) + m.open.size() * sizeof(PressureNode) + m.walls.size() * sizeof(WallLink);
  // Over all ranks (each holds its halo besides its nodes).
  double all = 0;
  for (double t : m.comm.all_gather({total})) all += t;
  return all / static_cast<double>(m.global_fluid);
}

double update_bytes(Precision precision) {
  const double pop = precision == Precision::kFloat ? sizeof(float) : sizeof(double);
  return 2 * kQ * pop + 0.5 * (kQ - 1) * sizeof(std::uint32_t);
}

double FlowSolver::bytes_moved_per_update() const {
  const Impl& m = *impl_;
  double bits_blocks = 0;  // blocks whose odd sweep reads their consecutive-line bits
  for (int c = 0; c < m.chunks && !m.consecutive.empty(); ++c)
    if (m.chunk_consecutive[static_cast<std::size_t>(c)]) bits_blocks += static_cast<double>(m.chunk_start(c + 1) - m.chunk_start(c)) / kBatch;
  const double per_step = static_cast<double>(m.stride) * update_bytes(m.settings.precision) + 0.5 * bits_blocks * sizeof(std::uint32_t);
  return per_step / static_cast<double>(m.fluid);
}

}  // namespace cmp::lbm
