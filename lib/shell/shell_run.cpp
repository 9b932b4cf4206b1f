#include "shell/shell_run.hpp"

#include "shell/rest_mesh.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "mesh/manifold.hpp"

#include <cmath>
#include <limits>

namespace cmp::shell {

void check_closed_shell_mesh(const mesh::TriMesh& m, const std::string& path) {
  try {
    check_rest_mesh(m, "mesh");
  } catch (const UsageError& e) {
    throw InputError(path, 0, std::string(e.what()).substr(6));  // without "mesh: "
  }
  const auto report = mesh::manifold_report(m.F, static_cast<int>(m.V.rows()));
  if (report.unused_vertices > 0 || !report.closed_manifold())
    throw InputError(path, 0, "a pressurised shell needs a closed manifold mesh with every vertex in a face (" +
                                  report.describe() + ")");
  if (!report.consistently_oriented())
    throw InputError(path, 0, "the faces are not consistently oriented (" + report.describe() +
                                  "); orient them, e.g. with rndmesh's tools or MeshLab");
  const auto shells = shell_partition(m.F, static_cast<int>(m.V.rows()));
  std::vector<double> v(static_cast<std::size_t>(shells.shell_count), 0.0);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    v[shells.face_shell[f]] += a.dot(b.cross(c)) / 6.0;
  }
  for (std::size_t s = 0; s < v.size(); ++s)
    if (!(v[s] > 0))
      throw InputError(path, 0, "the faces of shell " + std::to_string(s) +
                                    " are oriented inward (signed volume <= 0): a shell's faces must run "
                                    "counter-clockwise seen from outside");
}

std::vector<Plane> plates(double z_centre, double gap) {
  return {Plane{Eigen::Vector3d(0, 0, z_centre - 0.5 * gap), Eigen::Vector3d::UnitZ()},
          Plane{Eigen::Vector3d(0, 0, z_centre + 0.5 * gap), -Eigen::Vector3d::UnitZ()}};
}

namespace {
double z_centre(const mesh::VertexMatrix& V) { return 0.5 * (V.col(2).minCoeff() + V.col(2).maxCoeff()); }
}  // namespace

void check_walls_clear(const mesh::TriMesh& m, double gap, double vertex_radius) {
  const double lo = m.V.col(2).minCoeff(), hi = m.V.col(2).maxCoeff();
  if (!(gap > 0) || hi - lo + 2 * vertex_radius > gap)
    throw UsageError("--walls: plates " + io::format_number(gap) + " apart cut the mesh (its height is " +
                     io::format_number(hi - lo) + " plus the vertex radius " + io::format_number(vertex_radius) +
                     " on each side): choose a gap of at least " + io::format_number(hi - lo + 2 * vertex_radius));
}

ShellRunResult run_shell(const mesh::TriMesh& rest, const ShellRunOptions& o,
                         const std::function<void(const ShellRunRow&)>& on_row, const RelaxProgress& progress) {
  ShellModel model = o.model;
  model.load.turgor = 0.0;
  model.walls = o.wall_gap.has_value();
  model.contact.walls.clear();
  // Inflate at a constant turgor; a constant-volume model switches to its volume control
  // once the shell is inflated.
  const bool constant_volume = model.pressure == "volume";
  ShellSystem s = make_shell_system(rest, model);
  if (!s.pressure()) throw UsageError("shellpack shell needs a pressure model");
  RelaxParameters rp = o.relax;
  rp.force_scale = default_force_scale(rest, model.material.youngs_modulus, model.material.thickness);
  ShellRunResult result;
  for (const auto& t : s.terms()) result.term_names.push_back(t->name());
  const double zc = z_centre(rest.V);
  int step = 0;
  const auto record = [&](const std::string& stage, double applied, double gap, const RelaxResult& rr) {
    if (!std::isfinite(s.x.sum())) throw ComputationError("step " + std::to_string(step) + ": the state is not finite");
    ShellRunRow row;
    row.step = step++;
    row.stage = stage;
    row.applied_pressure = applied;
    row.gap = gap;
    row.observables = observe(s, s.x);
    row.relax = rr;
    if (on_row) on_row(row);
    if (row.observables.folded_hinges > 0)
      throw ComputationError("step " + std::to_string(row.step) + " (" + stage + ", Pi = " +
                             io::format_number(s.pressure()->turgor()) + "): " +
                             std::to_string(row.observables.folded_hinges) +
                             " hinges folded over: the load inverts elements of the mesh (a pressure beyond what "
                             "this mesh and model can hold)");
    result.rows.push_back(std::move(row));
  };
  // Checked every few hundred FIRE iterations too: a load that turns elements inside out
  // may never converge, and the run should say so at once rather than at the iteration cap.
  const RelaxProgress watch = [&](long iterations, double residual) {
    if (const long folded = folded_hinges(s, s.x); folded > 0)
      throw ComputationError("step " + std::to_string(step) + " (Pi = " + io::format_number(s.pressure()->turgor()) +
                             "): " + std::to_string(folded) + " hinges folded over after " + std::to_string(iterations) +
                             " FIRE iterations: the load inverts elements of the mesh");
    return !progress || progress(iterations, residual);
  };
  const auto relax_now = [&] { return relax(s, rp, watch); };
  for (int k = 1; k <= o.pressure_steps; ++k) {
    const double pi = o.pressure * k / o.pressure_steps;
    s.pressure()->set_turgor(pi);
    // Inflation runs at fixed turgor: a constant-volume model's update rule stays off.
    RelaxResult rr;
    if (constant_volume) {
      RelaxParameters fixed = rp;
      fixed.max_volume_updates = 0;
      fixed.volume_tolerance = std::numeric_limits<double>::infinity();
      rr = relax(s, fixed, watch);
    } else {
      rr = relax_now();
    }
    record("inflate", pi, 0.0, rr);
  }
  if (o.wall_gap) {
    if (constant_volume) s.pressure()->set_target_volumes(s.pressure()->volumes(span_of(s.x)));
    for (int k = 0; k <= o.squeeze_steps; ++k) {
      const double gap = *o.wall_gap * (1.0 - o.squeeze * k / o.squeeze_steps);
      s.walls()->set_walls(plates(zc, gap));
      record("squeeze", o.pressure, gap, relax_now());
    }
  }
  result.final_state = s.x;
  return result;
}

void write_shell_table(std::ostream& out, const ShellRunResult& r, const ShellRunOptions& o,
                       const std::string& provenance) {
  io::CsvWriter csv(out);
  const auto& m = o.model;
  csv.meta("provenance", provenance);
  csv.meta("units", "u = the mesh's length unit, P = the unit of E and --pressure; _u lengths, _u2 areas, "
                    "_u3 volumes, _P pressures, _F forces (P u^2), _W energies (P u^3); residual = max |f_i| / (E t a), "
                    "a the mean rest edge length");
  write_model_meta(csv, m, "t");
  csv.meta("relative_force_tolerance", io::format_number(o.relax.relative_tolerance));
  csv.meta("volume_rule", volume_rule_name(o.relax.volume_rule));
  std::vector<std::string> header{"step",         "stage",          "pressure_P",    "turgor_P",     "gap_u",
                                  "volume_u3",    "area_u2",        "gyration1_u2",  "gyration2_u2", "gyration3_u2",
                                  "asphericity_u2", "wall_force_F", "wall_contact_area_u2", "shell_contact_area_u2",
                                  "energy_W"};
  for (const auto& n : r.term_names) header.push_back("energy_" + n + "_W");
  for (const char* c : {"iterations", "volume_updates", "stop", "residual", "volume_error", "folded_hinges"})
    header.push_back(c);
  csv.header(header);
  const auto f = [](double v) { return io::format_number(v); };
  for (const auto& row : r.rows) {
    const auto& ob = row.observables;
    std::vector<std::string> cells{std::to_string(row.step), row.stage, f(row.applied_pressure), f(ob.turgor),
                                   f(row.gap), f(ob.volume), f(ob.area), f(ob.gyration[0]), f(ob.gyration[1]),
                                   f(ob.gyration[2]), f(ob.asphericity), f(ob.wall_force), f(ob.wall_contact_area),
                                   f(ob.shell_contact_area), f(ob.energy)};
    for (double e : ob.term_energies) cells.push_back(f(e));
    cells.push_back(std::to_string(row.relax.iterations));
    cells.push_back(std::to_string(row.relax.volume_updates));
    cells.push_back(relax_stop_name(row.relax.stop));
    cells.push_back(f(row.relax.residual));
    cells.push_back(f(row.relax.volume_error));
    cells.push_back(std::to_string(ob.folded_hinges));
    csv.row(cells);
  }
}

}  // namespace cmp::shell
