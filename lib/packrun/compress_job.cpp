#include "packrun/compress_job.hpp"

#include "shell/penetration.hpp"

#include "mesh/dual_areas.hpp"

#include "cli/progress.hpp"
#include "cli/seed_range.hpp"
#include "cli/value_list.hpp"
#include "core/errors.hpp"
#include "core/fnv1a.hpp"
#include "forcefield/hertz.hpp"
#include "io/atomic_output.hpp"
#include "io/checkpoint_file.hpp"
#include "io/csv.hpp"
#include "io/off.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace cmp::packrun {

namespace {

// 2: a checksum of the state follows it (io::CheckpointOutput); 1 had none.
constexpr const char* kMagic = "shellpack compress checkpoint 2";
constexpr const char* kWhat = "a shellpack compress checkpoint";

// v rounded to 12 significant digits (the targets as a user reads them back), through the
// strict parser like every other number.
double round12(double v) {
  double out = v;
  io::try_parse_double(fmt::format("{:.12g}", v), out);
  return out;
}

std::string join(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : " ") + io::format_number(x);
  return s;
}

// The cells of a row as format_row joins them, empty ones kept (also the last: "a,b," is
// three cells).
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = line.find(',', begin);
    cells.push_back(line.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (comma == std::string::npos) return cells;
    begin = comma + 1;
  }
}

}  // namespace

std::vector<double> parse_phi_targets(const std::string& text) {
  std::vector<double> out = cli::parse_value_list(text);
  for (double& v : out) v = round12(v);
  if (out.empty()) throw UsageError("no target given");
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (!(out[k] > 0) || out[k] > 1)
      throw UsageError("target " + io::format_number(out[k]) + " must lie in (0, 1] (a volume fraction)");
    if (k > 0 && !(out[k] > out[k - 1])) throw UsageError("the targets must increase, got '" + text + "'");
  }
  return out;
}

std::vector<std::string> compress_checkpoint_args(const std::string& path) {
  auto in = io::open_checkpoint(path);
  return io::read_checkpoint_header(in, path, kMagic, kWhat, true);
}

namespace {

// What to change when shells passed through each other. The hertz-faces barrier holds a vertex
// with at most the Hertz force at full overlap, h = delta; the turgor presses a vertex with
// about Pi times its dual area: past that the vertex goes through.
std::string penetration_advice(const shell::ShellSystem& s, const shell::ShellModel& m) {
  if (m.shell_contact_style != "hertz-faces") return "raise --vertex-radius or lower --step";
  const mesh::VertexMatrix V = Eigen::Map<const mesh::VertexMatrix>(s.x.data(), s.vertex_count(), 3);
  const Eigen::VectorXd area = mesh::vertex_dual_areas(V, s.rest().F);
  const auto& turgor = s.pressure()->turgors();
  const auto& shell_of = s.shells().vertex_shell;
  double load = 0;
  for (long v = 0; v < s.vertex_count(); ++v) load = std::max(load, std::abs(turgor[shell_of[v]]) * area[v]);
  const double delta = m.contact.contact_distance;
  const double barrier = hertz_force(hertz_prefactor(m.contact.vertex_effective_modulus(), 0.5 * delta), delta);
  return fmt::format("the face barrier holds a vertex with at most {:.3g} E D0^2 (delta = {}), the turgor presses one "
                     "with up to {:.3g}: raise --contact-distance, refine the mesh or lower --step",
                     barrier / m.material.youngs_modulus, io::format_number(delta), load / m.material.youngs_modulus);
}

}  // namespace

double default_vertex_radius(double thickness, double max_circumradius) {
  return std::max(thickness, 0.75 * max_circumradius);
}

namespace {

// The job's options with the contact model completed: the contact takes the shells' material,
// the vertex radius and contact distance their defaults (which need the mesh and the sphere
// sizes), and shells touch each other.
shell::CompressionOptions resolved_options(const CompressJob& job, const io::SpherePackingFrame& spheres,
                                           const mesh::TriMesh& cell) {
  shell::CompressionOptions o = job.run;
  auto& m = o.model;
  m.contact.youngs_modulus = m.material.youngs_modulus;
  m.contact.poisson_ratio = m.material.poisson_ratio;
  const double largest = spheres.radii.maxCoeff() / spheres.radii.mean();
  m.contact.vertex_radius = job.vertex_radius > 0
                                ? job.vertex_radius
                                : default_vertex_radius(m.material.thickness, shell::max_circumradius(cell) * largest);
  m.contact.contact_distance = job.contact_distance > 0 ? job.contact_distance : m.material.thickness;
  m.shell_contacts = true;
  return o;
}

// The shells at the jammed spheres: each sized so that, inflated at Pi_0, it fills its sphere's
// envelope; this far apart (the contact's reach) they start free of contact.
shell::ShellPacking start_packing(const CompressJob& job, const io::SpherePackingFrame& spheres,
                                  const mesh::TriMesh& cell, const shell::CompressionOptions& o) {
  const auto& m = o.model;
  shell::ShellModel inflate = m;
  inflate.load.turgor = o.turgor0;
  const double rest_diameter = shell::rest_diameter_for_inflated(cell, inflate, o.relax);
  const double reach = m.shell_contact_style == "hertz-faces" ? m.contact.contact_distance : 2.0 * m.contact.vertex_radius;
  return shell::place_shells(spheres, cell, rest_diameter, reach, job.seed);
}

// What defines the shells (the checkpoint records it): a resume with other inputs is refused
// rather than continuing someone else's state.
std::uint64_t shells_fingerprint(const CompressJob& job, const io::SpherePackingFrame& spheres,
                                 const mesh::TriMesh& cell, const shell::CompressionOptions& o) {
  const auto& m = o.model;
  Fnv1a fp;
  fp.bytes(spheres.centres.data(), sizeof(double) * static_cast<std::size_t>(spheres.centres.size()));
  fp.bytes(spheres.radii.data(), sizeof(double) * static_cast<std::size_t>(spheres.radii.size()));
  fp.bytes(spheres.box.data(), 3 * sizeof(double));
  fp.bytes(cell.V.data(), sizeof(double) * static_cast<std::size_t>(cell.V.size()));
  fp.bytes(cell.F.data(), sizeof(int) * static_cast<std::size_t>(cell.F.size()));
  fp.value(job.seed);
  fp.value(m.contact.vertex_radius);
  if (m.shell_contact_style == "hertz-faces") fp.value(m.contact.contact_distance);
  if (o.walls) {
    fp.value(o.phi_start);
    fp.value(m.contact.wall_modulus);
  }
  return fp.h;
}

// The columns of compress.csv and its rows as text (a checkpoint stores the rows as written,
// so that a resumed run's table is the same bytes).
struct CompressTable {
  bool walls = false;    // wall_pressure_E, coverage, their ratio
  bool timings = false;  // seconds
  std::vector<std::string> header;

  CompressTable(const std::vector<std::string>& term_names, bool walls_, bool timings_)
      : walls(walls_), timings(timings_) {
    header = {"step",   "phi",       "dphi",       "box_side_d0",   "pressure_E",
              "turgor_mean_P0", "turgor_cv", "Z", "dZ", "contacts",
              "asphericity_mean_d02", "delta_eps_mean", "volume_error", "energy_Ed3"};
    for (const auto& t : term_names) header.push_back("energy_" + t + "_Ed3");
    if (walls)
      for (const char* c : {"wall_pressure_E", "coverage", "wall_pressure_over_coverage_E"}) header.push_back(c);
    for (const char* c : {"residual", "iterations", "volume_updates", "stop"}) header.push_back(c);
    if (timings) header.push_back("seconds");
  }

  // One row, its cells in the header's order.
  std::string format_row(const shell::CompressionRow& r, double seconds) const {
    const auto f = [](double v) { return io::format_number(v); };
    std::string s = std::to_string(r.step);
    for (double v : {r.phi, r.dphi, r.box_side, r.pressure, r.turgor_mean, r.turgor_cv, r.Z, r.dZ})
      s += "," + f(v);
    s += "," + std::to_string(r.contacts);
    for (double v : {r.asphericity, r.delta_eps, r.volume_error, r.energy}) s += "," + f(v);
    for (double e : r.term_energies) s += "," + f(e);
    if (walls)
      s += "," + f(r.wall_pressure) + "," + f(r.coverage) + "," +
           (r.coverage > 0 ? f(r.wall_pressure / r.coverage) : std::string());  // empty while undefined
    s += "," + f(r.relax.residual) + "," + std::to_string(r.relax.iterations) + "," +
         std::to_string(r.relax.volume_updates) + "," + shell::relax_stop_name(r.relax.stop);
    if (timings) s += "," + f(seconds);
    return s;
  }

  // A row restored from a checkpoint has `seconds` when the run that wrote it had --timings,
  // which a resume may add or drop: the row is brought to this run's columns (an empty
  // `seconds` where its time is unknown, none where this run has no timings).
  std::string restored_row(std::string row, std::uint64_t index, const std::string& checkpoint) const {
    const std::size_t untimed_cells = header.size() - (timings ? 1 : 0);
    const std::size_t cells = split_cells(row).size();
    if (cells == untimed_cells && timings) return row + ",";
    if (cells == untimed_cells + 1 && !timings) return row.substr(0, row.rfind(','));
    if (cells == untimed_cells || cells == untimed_cells + 1) return row;
    throw InputError(checkpoint, 0,
                     fmt::format("row {} of the table has {} cells where this run has {} (or {} with --timings): "
                                 "truncated or damaged checkpoint",
                                 index, cells, untimed_cells, untimed_cells + 1));
  }
};

// Rows a checkpoint may hold before it is taken for damaged (a cut length read as a count).
constexpr std::size_t kMaxRows = 100'000'000;

// One run of `shellpack compress`: the protocol (shell::Compression) and what the job keeps
// beside it (the table's rows, the last converged state, the provenance, the progress bar),
// with the outputs written from them. run_compress_job calls the methods in the order of a
// run; every way out of a box step saves the checkpoint first, so that a stopped or failed run
// continues with --resume from its last converged step.
class CompressRun {
 public:
  using clock = std::chrono::steady_clock;

  CompressRun(const CompressJob& job, const std::string& provenance, const io::SpherePackingFrame& spheres,
              const mesh::TriMesh& cell)
      : job_(job),
        o_(resolved_options(job, spheres, cell)),
        run_(start_packing(job, spheres, cell, o_), o_),
        n_shells_(static_cast<long>(run_.packing().shell_vertex_counts.size())),
        fingerprint_(shells_fingerprint(job, spheres, cell, o_)),
        provenance_(provenance),
        bar_("compressing", 1.0, job.quiet),
        table_(run_.term_names(), o_.walls, job.timings),
        // The walls: "rigid" or their Young's modulus E_w [E].
        wall_name_(std::isinf(o_.model.contact.wall_modulus)
                       ? std::string("rigid")
                       : io::format_number(o_.model.contact.wall_modulus / o_.model.material.youngs_modulus)) {}

  bool done() const { return run_.done(); }

  // A new run: the shells inflated at Pi_0 in the start box, the table's first row.
  void start() {
    const auto step_start = clock::now();
    note(0);
    const auto row0 = run_.start(progress());
    if (!row0.relax.converged())
      throw ComputationError(fmt::format("inflating the shells at Pi_0 stopped by {} at residual {} after {} FIRE "
                                         "iterations (raise --fire-max-iterations)",
                                         shell::relax_stop_name(row0.relax.stop), io::format_number(row0.relax.residual),
                                         row0.relax.iterations));
    rows_.push_back(table_.format_row(row0, seconds_since(step_start)));
  }

  // A resumed run: the state, provenance and rows saved by save(), refused when the checkpoint
  // is of other inputs (its fingerprint, or a state of another size).
  void restore() {
    auto in = io::open_checkpoint(job_.resume);
    io::read_checkpoint_header(in, job_.resume, kMagic, kWhat, true);
    io::CheckpointReader r(in, job_.resume);
    if (r.get<std::uint64_t>() != fingerprint_)
      throw InputError(job_.resume, 0,
                       "the checkpoint belongs to another run (its sphere packing, cell mesh, seed or vertex radius "
                       "differ from these)");
    provenance_ = r.get_string(1 << 20);
    shell::CompressionState st;
    st.step = r.get<long>();
    for (int a = 0; a < 3; ++a) st.box[a] = r.get<double>();
    st.next_target = r.get<std::uint64_t>();
    st.phi_jammed = r.get<double>();
    const auto x = r.get_vector<double>(static_cast<std::uint64_t>(run_.system().x.size()));
    st.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    st.turgor = r.get_vector<double>(static_cast<std::uint64_t>(n_shells_));
    st.volume0 = r.get_vector<double>(static_cast<std::uint64_t>(n_shells_));
    const auto n_rows = r.get<std::uint64_t>();
    if (n_rows > kMaxRows) throw InputError(job_.resume, 0, "truncated or damaged checkpoint");
    for (std::uint64_t k = 0; k < n_rows; ++k) rows_.push_back(table_.restored_row(r.get_string(1 << 20), k, job_.resume));
    try {
      run_.restore(st);
    } catch (const std::invalid_argument&) {
      throw InputError(job_.resume, 0, "the checkpoint belongs to another run (a state of another size)");
    }
  }

  // Periodic targets must lie above phi_J, known only once the shells are inflated (a resume
  // may name targets the run has passed: those are skipped; the walls start below phi_J).
  void check_targets() const {
    for (double t : run_.options().targets)  // phi (a --dphi list resolved by start/restore)
      if (t < run_.phi_jammed() && job_.resume.empty() && !o_.walls)
        throw UsageError(fmt::format("--phi: target {} is below the starting volume fraction phi_J = {} of these shells",
                                     io::format_number(t), io::format_number(run_.phi_jammed())));
  }

  // Before the first box step: the start is the state to save, the bar measures phi from it to
  // the last target, and the table's file is opened (it is written once, at the end).
  void begin_steps() {
    remember();
    phi_from_ = o_.walls ? o_.phi_start : run_.phi_jammed();
    span_ = std::max(run_.options().targets.back() - phi_from_, 1e-12);
    bar_.update(0);
    if (!job_.csv.empty()) csv_out_.emplace(job_.csv);
    last_checkpoint_ = clock::now();
  }

  // One box step: relaxed, checked, recorded (a row, the packing at a target) and remembered
  // as the state to save; saved every checkpoint_every seconds.
  void step() {
    const auto step_start = clock::now();
    const shell::CompressionRow row = advance();
    fail_unless_converged(row);
    check_penetration(row);
    rows_.push_back(table_.format_row(row, seconds_since(step_start)));
    // A packing that cannot be written (a full disk) is said after the table, which keeps the run.
    if (row.target) packings_.attempt([&] { write_packing(*row.target); });
    remember();
    bar_.update(std::min(1.0, (run_.phi() - phi_from_) / span_));
    note(row.relax.residual);
    if (seconds_since(last_checkpoint_) >= job_.checkpoint_every) {
      save();
      last_checkpoint_ = clock::now();
    }
  }

  // --stop-after-steps: the checkpoint and the table so far, and how to continue.
  void stop_as_asked(long steps) {
    save();
    bar_.finish();
    if (!job_.quiet)
      std::cerr << "shellpack: stopped after " << steps << " box steps as asked (phi " << run_.phi() << ")"
                << (job_.checkpoint.empty() ? "" : "; continue with shellpack compress --resume " + job_.checkpoint)
                << "\n";
    write_table();
  }

  // The last target reached: the final checkpoint, the table and the summary.
  void finish() {
    save();
    bar_.finish();
    write_table();
    if (!job_.quiet)
      std::cerr << "shellpack: " << run_.step_index() << " box steps from phi_J " << io::format_number(run_.phi_jammed())
                << " to " << io::format_number(run_.phi()) << "\n";
  }

 private:
  static double seconds_since(clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); }

  void note(double residual) {
    bar_.set_note(fmt::format("phi {:.4f}, step {}, residual {:.2e}", run_.phi(), run_.step_index(), residual));
  }
  // The relaxations report to the bar's note as they go.
  shell::RelaxProgress progress() {
    return [this](long, double residual) {
      note(residual);
      return true;
    };
  }

  // A relaxation that throws leaves the last converged state saved.
  shell::CompressionRow advance() {
    try {
      return run_.advance(progress());
    } catch (const ComputationError&) {
      save();
      throw;
    }
  }

  void fail_unless_converged(const shell::CompressionRow& row) {
    if (row.relax.converged()) return;
    save();
    bar_.finish();
    throw ComputationError(fmt::format(
        "step {} (phi {}): the relaxation stopped by {} at residual {} (tolerance {}) after {} FIRE iterations{}",
        row.step, io::format_number(row.phi), shell::relax_stop_name(row.relax.stop),
        io::format_number(row.relax.residual), io::format_number(o_.relax.relative_tolerance), row.relax.iterations,
        job_.checkpoint.empty() ? std::string()
                                : "; the checkpoint " + job_.checkpoint +
                                      " holds the last converged step (continue with --resume, e.g. with a higher "
                                      "--fire-max-iterations)"));
  }

  // After every step: a vertex inside another shell ends the run (the checkpoint keeps the last
  // step without one).
  void check_penetration(const shell::CompressionRow& row) {
    if (!job_.check_penetration) return;
    const auto& s = run_.system();
    const auto found = shell::penetrations(s.x, s.rest().F, s.shells(), run_.box(), run_.packing().periodic);
    if (found.empty()) return;
    save();
    bar_.finish();
    throw ComputationError(fmt::format(
        "step {} (phi {}): vertex {} of shell {} lies inside shell {} ({} vertices inside other shells): the shells "
        "pass through each other; {}{}",
        row.step, io::format_number(row.phi), found.front().vertex, found.front().vertex_shell, found.front().shell,
        found.size(), penetration_advice(s, o_.model),
        job_.checkpoint.empty() ? "" : "; the checkpoint " + job_.checkpoint + " holds the step before"));
  }

  // The state after the last converged step, and the rows up to it: what save() writes.
  void remember() {
    saved_ = run_.state();
    saved_rows_ = rows_.size();
  }

  // The checkpoint (restore() reads it back in this order; its layout is the file format).
  void save() {
    if (job_.checkpoint.empty() || !saved_) return;
    io::CheckpointOutput out(job_.checkpoint, kMagic, job_.checkpoint_args);
    auto& s = out.stream();
    io::put(s, fingerprint_);
    io::put(s, provenance_);
    io::put(s, saved_->step);
    for (int a = 0; a < 3; ++a) io::put(s, saved_->box[a]);
    io::put(s, static_cast<std::uint64_t>(saved_->next_target));
    io::put(s, saved_->phi_jammed);
    io::put(s, std::vector<double>(saved_->x.data(), saved_->x.data() + saved_->x.size()));
    io::put(s, saved_->turgor);
    io::put(s, saved_->volume0);
    io::put(s, static_cast<std::uint64_t>(saved_rows_));
    for (std::size_t k = 0; k < saved_rows_; ++k) io::put(s, rows_[k]);
    out.commit();
  }

  // compress.csv: the run's parameters as `# key=value` lines, then every row so far.
  void write_table() {
    if (!csv_out_) return packings_.commit_then_throw({});
    const auto& m = o_.model;
    io::CsvWriter csv(csv_out_->stream());
    csv.meta("provenance", provenance_);
    csv.meta("units", "lengths in D0 (the inflated shell's volume-equivalent diameter), pressures and moduli in E "
                      "(_E) or Pi_0 (_P0), energies in E D0^3 (_Ed3); residual = max |f_i| / (E t a), a the mean rest "
                      "edge length; pressure = contact virial");
    shell::write_model_meta(csv, m, "thickness");
    csv.meta("P0", io::format_number(o_.turgor0));
    csv.meta("box_step", io::format_number(o_.step));
    csv.meta("relative_force_tolerance", io::format_number(o_.relax.relative_tolerance));
    if (o_.between_tolerance > 0) csv.meta("between_force_tolerance", io::format_number(o_.between_tolerance));
    csv.meta("volume_rule", shell::volume_rule_name(o_.relax.volume_rule));
    csv.meta("seed", std::to_string(job_.seed));
    csv.meta("shells", std::to_string(n_shells_));
    csv.meta("vertices_per_shell", std::to_string(run_.packing().shell_vertex_counts.front()));
    csv.meta("phi_J", io::format_number(run_.phi_jammed()));
    if (o_.walls) {
      csv.meta("walls", wall_name_);
      csv.meta("phi_start", io::format_number(o_.phi_start));
    }
    csv.header(table_.header);
    for (const auto& r : rows_) csv.row(split_cells(r));
    packings_.commit_then_throw({&*csv_out_});
  }

  // The packing OFF at a target (-o with {phi}), its parameters as `# key=value` comments
  // (docs/formats.md).
  void write_packing(std::size_t target) {
    const double phi = run_.options().targets[target];
    const auto& s = run_.system();
    if (job_.output_pattern.empty()) return;
    const auto& m = o_.model;
    io::PackingInfo info;
    info.box = run_.box();
    info.periodic = run_.packing().periodic;
    info.shell_vertex_counts = run_.packing().shell_vertex_counts;
    const auto* p = s.pressure();
    std::vector<std::string> comments{provenance_,
                                      "D0=1",
                                      "phi=" + io::format_number(phi),
                                      "E=" + io::format_number(m.material.youngs_modulus),
                                      "nu=" + io::format_number(m.material.poisson_ratio),
                                      "thickness=" + io::format_number(m.material.thickness),
                                      "vertex_radius=" + io::format_number(m.contact.vertex_radius),
                                      "contact=" + m.shell_contact_style,
                                      "P0=" + io::format_number(o_.turgor0),
                                      "bending=" + (m.bending.empty() ? std::string("none") : m.bending),
                                      "stretching=" + m.stretching,
                                      "pressure_model=" + m.pressure,
                                      "step=" + std::to_string(run_.step_index()),
                                      "turgor=" + join(p->turgors()),
                                      "volume0=" + join(p->target_volumes())};
    if (m.shell_contact_style == "hertz-faces")
      comments.push_back("contact_distance=" + io::format_number(m.contact.contact_distance));
    if (o_.walls) comments.push_back("walls=" + wall_name_);
    mesh::VertexMatrix V = Eigen::Map<const mesh::VertexMatrix>(s.x.data(), s.vertex_count(), 3);
    io::write_off(cli::expand_pattern(job_.output_pattern, "phi", io::format_number(phi)), V, s.rest().F, comments,
                  &info);
  }

  const CompressJob& job_;
  const shell::CompressionOptions o_;  // the job's, the contact model completed
  shell::Compression run_;
  const long n_shells_;
  const std::uint64_t fingerprint_;
  std::string provenance_;  // this command's, or the checkpoint's on a resume
  std::vector<std::string> rows_;
  cli::ProgressBar bar_;
  const CompressTable table_;
  const std::string wall_name_;
  std::optional<shell::CompressionState> saved_;  // the last converged step
  std::size_t saved_rows_ = 0;
  double phi_from_ = 0, span_ = 1;  // the bar: phi from the start to the last target
  std::optional<io::AtomicOutput> csv_out_;
  io::SecondaryOutputs packings_;  // the OFF at each target
  clock::time_point last_checkpoint_;
};

}  // namespace

void run_compress_job(const CompressJob& job, const std::string& provenance) {
  // Inputs, checked before any work.
  const auto spheres = shell::read_start_packing(job.packing_path);
  const auto off = io::read_off(job.mesh_path);
  const auto cell = shell::normalised_cell(mesh::TriMesh{off.V, off.F}, job.mesh_path);
  CompressRun run(job, provenance, spheres, cell);
  if (job.resume.empty())
    run.start();
  else
    run.restore();
  run.check_targets();
  run.begin_steps();
  for (long steps_here = 0; !run.done(); ++steps_here) {
    if (job.stop_after_steps > 0 && steps_here >= job.stop_after_steps) {
      run.stop_as_asked(steps_here);
      return;
    }
    run.step();
  }
  run.finish();
}

}  // namespace cmp::packrun
