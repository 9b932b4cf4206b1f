#include "flowrun/flow_run.hpp"

#include "cli/progress.hpp"
#include "flowrun/checkpoint_file.hpp"

#include <fmt/format.h>

#include <chrono>

namespace cmp::flowrun {

FlowRun::FlowRun(FlowCase& c, const RunPlan& plan) : case_(c), plan_(plan) {
  // Every rank holds the pore mask (1 byte a node); the populations are cut over the ranks.
  plan.comm.agree([&] { c.make_lattice(); });
  solver_ = std::make_unique<lbm::FlowSolver>(c.lattice, plan.flow, plan.comm);
  if (!plan.resume.empty()) earlier_ = load_checkpoint(plan.resume, *solver_, plan.comm);
}

FlowRun::~FlowRun() = default;

FlowOutcome FlowRun::run() {
  using clock = std::chrono::steady_clock;
  FlowOutcome out;
  out.fluid_nodes = solver_->fluid_nodes();
  out.bytes_per_fluid_node = solver_->bytes_per_fluid_node();
  out.interpolated_links = solver_->interpolated_links();
  const long first_step = solver_->steps();
  const auto start = clock::now();
  auto last_checkpoint = start;
  std::vector<lbm::FlowObservables> checks = earlier_;  // what a checkpoint records
  const auto save = [&] {
    if (plan_.checkpoint.empty()) return;
    write_checkpoint(plan_.checkpoint, plan_.checkpoint_args, *solver_, checks, plan_.comm);
    last_checkpoint = clock::now();
  };
  {
    cli::ProgressBar bar("lbflow " + case_.file, static_cast<double>(plan_.convergence.max_steps),
                         plan_.quiet || !plan_.comm.root());
    bar.update(static_cast<double>(first_step));
    out.result = lbm::run_to_steady_state(
        *solver_, plan_.convergence,
        [&](const lbm::FlowObservables& o) {
          checks.push_back(o);
          if (bar.enabled()) {
            const auto change = relative_change(checks, checks.size() - 1, plan_.convergence.window);
            bar.set_note(fmt::format("step {}, kappa {:.6g} lu, change {}", o.steps, o.kappa_lu,
                                     change ? fmt::format("{:.2g} (tol {:.2g})", *change, plan_.convergence.tol)
                                            : std::string("-")));
            bar.update(static_cast<double>(o.steps));
          }
          // Rank 0's clock decides for every rank (saving is collective).
          if (!plan_.checkpoint.empty() &&
              plan_.comm.broadcast_flag(std::chrono::duration<double>(clock::now() - last_checkpoint).count() >=
                                        plan_.checkpoint_every))
            save();
        },
        earlier_);
  }
  out.seconds = std::chrono::duration<double>(clock::now() - start).count();
  out.steps_run = solver_->steps() - first_step;
  const double width = plan_.flow.precision == lbm::Precision::kFloat ? 4 : 8;
  for (double slots : plan_.comm.all_gather({solver_->halo_slots_per_step()})) out.halo_bytes_per_step += width * slots;
  out.halo_seconds = solver_->halo_seconds();
  save();
  return out;
}

void FlowRun::start_from(const lbm::StartState& state) {
  solver_->start_from(state);
  earlier_.clear();
}

CoarseFlow FlowRun::coarse_flow() const {
  CoarseFlow c;
  c.voxels = case_.voxels;
  c.refine = case_.refine;
  c.settings = plan_.flow;
  // Gathered on rank 0, then shared (the other ranks add nothing to the concatenation).
  c.density = plan_.comm.all_gather(solver_->density_field());
  c.velocity = plan_.comm.all_gather(solver_->velocity_field());
  return c;
}

FlowField FlowRun::field(const FlowOutcome& outcome) const {
  FlowField f;
  f.dims = {case_.lattice.nx, case_.lattice.ny, case_.lattice.nz};
  f.origin = case_.node_origin;
  f.spacing = case_.node_spacing;
  f.velocity = solver_->velocity_field();
  f.density = solver_->density_field();
  f.fluid = case_.lattice.fluid;
  if (case_.delta) f.field_data.emplace_back("delta", *case_.delta);
  if (case_.d0) f.field_data.emplace_back("d0", *case_.d0);
  if (case_.scale) f.field_data.emplace_back("scale", *case_.scale);
  f.field_data.emplace_back("refine", case_.refine);
  f.field_data.emplace_back("permeability_lu", outcome.result.final.kappa_lu);
  f.field_data.emplace_back("tortuosity", outcome.result.final.tortuosity);
  return f;
}

}  // namespace cmp::flowrun
