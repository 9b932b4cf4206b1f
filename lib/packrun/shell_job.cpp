#include "packrun/shell_job.hpp"

#include "cli/progress.hpp"
#include "io/atomic_output.hpp"
#include "io/off.hpp"

#include <iostream>
#include <optional>

namespace cmp::packrun {

void run_shell_job(const ShellJob& job, const std::string& provenance) {
  const auto& o = job.run;
  const auto off = io::read_off(job.mesh_path);
  mesh::TriMesh rest{off.V, off.F};
  shell::check_closed_shell_mesh(rest, job.mesh_path);
  if (o.wall_gap) shell::check_walls_clear(rest, *o.wall_gap, o.model.contact.vertex_radius);
  std::optional<io::AtomicOutput> csv_out;
  if (!job.csv.empty()) csv_out.emplace(job.csv);
  const int total = o.pressure_steps + (o.wall_gap ? o.squeeze_steps + 1 : 0);
  cli::ProgressBar bar("relaxing", static_cast<double>(total), job.quiet);
  const auto result = shell::run_shell(rest, o, [&](const shell::ShellRunRow& row) {
    bar.update(static_cast<double>(row.step + 1));
    if (!row.relax.converged())
      std::cerr << "shellpack: warning: step " << row.step << " stopped by " << shell::relax_stop_name(row.relax.stop)
                << " at residual " << row.relax.residual << "\n";
  });
  bar.finish();
  if (csv_out) shell::write_shell_table(csv_out->stream(), result, o, provenance);
  io::SecondaryOutputs mesh_out;  // a mesh that cannot be written does not lose the table
  if (!job.mesh_output.empty()) {
    mesh::VertexMatrix V = Eigen::Map<const mesh::VertexMatrix>(result.final_state.data(), rest.V.rows(), 3);
    mesh_out.attempt([&] { io::write_off(job.mesh_output, V, rest.F, {provenance}); });
  }
  mesh_out.commit_then_throw({csv_out ? &*csv_out : nullptr});
  if (!job.quiet && !result.rows.empty()) {
    const auto& last = result.rows.back();
    std::cerr << "shellpack: " << result.rows.size() << " steps; last: Pi " << last.observables.turgor << ", volume "
              << last.observables.volume << ", " << shell::relax_stop_name(last.relax.stop) << " (residual "
              << last.relax.residual << ")\n";
  }
}

}  // namespace cmp::packrun
