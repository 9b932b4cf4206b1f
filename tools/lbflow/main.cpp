// lbflow: Stokes flow through the pore space by the D3Q19 lattice Boltzmann method:
// permeability and hydraulic tortuosity of percolate's clusters (thesis 5.2.3, 5.3.3, 5.5.3).
//   lbflow cluster.vtk --refine 3 > flow.csv                            permeability, tortuosity
//   lbflow cluster.vtk --refine 3 --tol 1e-6 --vtk flow.vtk > flow.csv  and the velocity field
//   lbflow image.raw --dims 96x96x96 --refine 1 --checkpoint run.chk    raw bytes; resumable
//   lbflow --resume run.chk > flow.csv                                  continue after an interruption
//   lbflow clusters/*.vtk --threads 2 > flows.csv                       many images, one row each
//   lbflow jammed.xyz --delta 0.04 --scale 1.1 > flow.csv               the packing itself: exact walls
//   mpirun -np 4 lbflow cluster.vtk --refine 3 > flow.csv                one flow on 4 MPI ranks, same bits
#include "cli/checkpoint_args.hpp"
#include "cli/seed_range.hpp"
#include "cli/value_list.hpp"
#include "cli/tool.hpp"
#include "core/errors.hpp"
#include "core/registry.hpp"
#include "flowrun/checkpoint_file.hpp"
#include "flowrun/flow_batch.hpp"
#include "flowrun/flow_case.hpp"
#include "flowrun/flow_run.hpp"
#include "io/csv.hpp"
#include "lbm/collision.hpp"
#include "lbm/communicator.hpp"
#include "voxel/percolation.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <csignal>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>

using namespace cmp;

namespace {

struct Options {
  cli::CommonOptions common;
  std::vector<std::string> inputs;
  std::string dims, collision = "mrt", axis = "x", drive = "pressure", precision = "double";
  std::string csv = "-", vtk, history, checkpoint, resume;
  std::string refine = "3";
  double tau = std::numeric_limits<double>::quiet_NaN(), magic = 3.0 / 16.0, density_drop = 1e-3, body_force = 1e-6;
  double delta = 0, scale = 1, d0 = 0, checkpoint_every = 300;
  double tol = 1e-6;
  long max_steps = 200000, check_every = 100, window = 10;
  bool list = false, timings = false, prolong = false;
};

// The options that only steer this process (not the run): left out of a checkpoint's arguments.
// The options that steer only this process, left out of a checkpoint's arguments.
constexpr cli::ProcessOnlyOption kProcessOnly[] = {
    {"--threads", true}, {"--resume", true}, {"-q", false}, {"--quiet", false}, {"--timings", false}};

void declare(cli::Tool& tool, Options& o) {
  auto& app = tool.app();
  // A resumed run repeats the checkpoint's arguments, then the ones typed: the last wins.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.add_option("inputs", o.inputs,
                 "pore images: binary VTK STRUCTURED_POINTS (percolate -o; non-zero = fluid), raw bytes with --dims, "
                 "or a sphere packing as extended XYZ (exact walls, with --delta); '-' reads any of them from stdin, told from "
                 "the content (raw bytes: with --dims)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  tool.declare_inputs(app, o.inputs);
  app.add_option("--dims", o.dims, "the inputs are raw bytes (x fastest, non-zero = fluid) of NXxNYxNZ voxels");
  app.add_option("-M,--refine", o.refine, "lattice refinement M: each voxel becomes M^3 nodes (thesis: 3); a list "
                                        "(1,2,3) solves each M in turn, one row per M")
      ->capture_default_str();
  tool.add_double(app, "--delta", o.delta, "sphere packings: voxel side [D0] (the node side is delta/M)",
                  cli::positive());
  tool.add_double(app, "--scale", o.scale, "sphere packings: multiply every radius by this factor (inflation)",
                  cli::positive());
  tool.add_double(app, "--d0", o.d0, "sphere packings: D0 [length units of the file]; 0: the file's D0=, else the "
                                     "mean diameter (as percolate)", cli::non_negative());
  app.add_option("--collision", o.collision, "collision model (--list-models)")->capture_default_str();
  app.add_flag("--list-models", o.list, "print the collision models and exit");
  app.add_flag("--prolong", o.prolong, "with a --refine list: start each M from the flow of the one before, prolonged "
                                       "(not faster on the clusters measured so far: docs/lbflow.md)");
  tool.add_double(app, "--tau", o.tau, "relaxation time of the shear moments; viscosity (tau - 1/2)/3 [lattice units]; "
                                     "default 0.55 on images (half-way walls: the same kappa as the thesis's 1, settled "
                                     "5-7 times sooner), 1 on sphere packings (interpolated walls move with tau)",
                  {0.5, std::numeric_limits<double>::infinity(), true, false});
  tool.add_double(app, "--magic", o.magic, "TRT/MRT magic parameter Lambda (3/16: walls half-way for every tau)",
                  cli::positive());
  app.add_option("--axis", o.axis, "flow axis x, y or z (the others are periodic)")->capture_default_str();
  app.add_option("--drive", o.drive, "'pressure': a density drop between inlet and outlet planes (as the thesis); "
                                     "'force': a body force in a fully periodic box")->capture_default_str();
  tool.add_double(app, "--density-drop", o.density_drop, "pressure drive: rho_in - rho_out [lattice units]",
                  cli::positive());
  tool.add_double(app, "--body-force", o.body_force, "force drive: force density along the axis [lattice units]",
                  cli::positive());
  app.add_option("--precision", o.precision, "storage of the populations: double or float (arithmetic in double)")
      ->capture_default_str();
  tool.add_double(app, "--tol", o.tol, "steady state: relative change of kappa and tau_H over --window checks",
                  cli::positive());
  tool.add_long(app, "--max-steps", o.max_steps, "step cap: exit 1 if not converged by then", cli::at_least(1));
  tool.add_long(app, "--check-every", o.check_every, "steps between convergence checks", cli::at_least(1));
  tool.add_long(app, "--window", o.window, "checks between the two values compared", cli::at_least(1));
  tool.add_output(app, "-o,--output", o.csv, "CSV, one row per input ('-': stdout)")->capture_default_str();
  tool.add_output(app, "--vtk", o.vtk, "velocity and density as VTK in the input's geometry (ParaView overlays it on the "
                                 "packing); several inputs: use {name}");
  tool.add_output(app, "--history", o.history, "CSV of kappa and tau_H at every convergence check ('-': stdout)");
  tool.add_output(app, "--checkpoint", o.checkpoint, "save the run here every --checkpoint-every seconds and at the end "
                                               "(atomic); one input only");
  tool.add_double(app, "--checkpoint-every", o.checkpoint_every, "seconds between checkpoints (0: every check)",
                  cli::non_negative());
  app.add_option("--resume", o.resume, "continue the run saved in this checkpoint (alone: with its arguments)");
  app.add_flag("--timings", o.timings,
               "add seconds, mlups (fluid-node updates per second), halo_bytes_per_step and halo_seconds (MPI ranks) to "
               "the CSV, and seconds and mlups to the summary on stderr, "
               "which it prints even with -q");
  tool.add_common(app, o.common, cli::Tool::kThreads | cli::Tool::kQuiet);
}

void print_models() {
  cmp::write_style_header(std::cout);
  cmp::write_styles(std::cout, "collision", lbm::collision_styles());
}

struct Plan {
  flowrun::RunPlan run;
  std::vector<std::string> vtk_names;
  std::vector<int> refinements;
};

// --refine: whole numbers from 1, ascending, no repeats.
std::vector<int> parse_refinements(const std::string& text) {
  std::vector<int> r;
  for (double v : cli::parse_value_list(text)) {
    if (!(v >= 1 && v <= 1e6 && v == std::floor(v)))  // (the lattice size is checked with the image)
      throw UsageError("must be whole numbers from 1, got " + io::format_number(v));
    if (!r.empty() && static_cast<int>(v) <= r.back())
      throw UsageError(fmt::format("must ascend without repeats (each M starts from the one before), got {} after {}",
                                   static_cast<int>(v), r.back()));
    r.push_back(static_cast<int>(v));
  }
  if (r.empty()) throw UsageError("needs at least one M");
  return r;
}

Plan check(cli::Tool& tool, const Options& o, const std::vector<std::string>& args) {
  Plan p;
  auto& f = p.run.flow;
  tool.check(!o.inputs.empty(), "", "no input given (a VTK image, raw bytes with --dims, a sphere packing XYZ, or --resume)");
  tool.check(std::count(o.inputs.begin(), o.inputs.end(), std::string("-")) <= 1, "",
             "'-' (standard input) given more than once: it can be read only once");
  tool.collect("--refine", [&] { p.refinements = parse_refinements(o.refine); });
  tool.check((o.checkpoint.empty() && o.resume.empty()) || p.refinements.size() <= 1, "--refine",
             "a checkpoint holds the run of one M: give one M with --checkpoint or --resume");
  tool.collect("--collision", [&] { lbm::collision_style(o.collision); });
  f.collision = o.collision;
  f.collision_parameters = {o.tau, o.magic};
  tool.collect("--axis", [&] { f.axis = voxel::axis_from_name("--axis", o.axis); });
  tool.check(o.drive == "pressure" || o.drive == "force", "--drive", "must be pressure or force, got '" + o.drive + "'");
  f.driving = o.drive == "force" ? lbm::Driving::kBodyForce : lbm::Driving::kPressure;
  f.density_drop = o.density_drop;
  f.body_force = o.body_force;
  tool.check(o.precision == "double" || o.precision == "float", "--precision",
             "must be double or float, got '" + o.precision + "'");
  f.precision = o.precision == "float" ? lbm::Precision::kFloat : lbm::Precision::kDouble;
  if (!o.dims.empty()) tool.collect("--dims", [&] { flowrun::parse_dims(o.dims); });
  p.run.convergence = {o.tol, o.check_every, o.window, o.max_steps};
  p.run.checkpoint = o.checkpoint;
  p.run.checkpoint_every = o.checkpoint_every;
  p.run.resume = o.resume;
  p.run.quiet = o.common.quiet;
  tool.check(o.checkpoint.empty() || o.inputs.size() <= 1, "--checkpoint",
             "takes one input (a checkpoint holds one run), got " + std::to_string(o.inputs.size()));
  tool.check(o.resume.empty() || o.inputs.size() <= 1, "--resume", "continues one run; give one input or none");
  int on_stdout = (o.csv == "-") + (o.vtk == "-") + (o.history == "-");
  tool.check(on_stdout <= 1, "", "at most one output may go to stdout ('-'): the CSV is there by default, send the "
                                 "others to files (or -o FILE)");
  std::set<std::string> names;
  for (const auto& in : o.inputs) {
    p.vtk_names.push_back(o.vtk.empty() ? "" : cli::expand_pattern(o.vtk, "name", std::filesystem::path(in).stem().string()));
    names.insert(p.vtk_names.back());
  }
  tool.check(o.vtk.empty() || names.size() == o.inputs.size(), "--vtk",
             "must tell the inputs apart with {name} when several are given, e.g. --vtk 'flow_{name}.vtk'");
  p.run.checkpoint_args = cli::checkpoint_arguments(args, kProcessOnly);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  lbm::Communicator comm;  // one process, until a launcher says otherwise
  int error_fd = 2;         // this rank's own standard error, for an error no other rank shares
  int status = cli::run_tool("lbflow", [&] {
    // Under mpirun or srun: every rank runs this main; rank 0 alone prints and writes.
    comm = lbm::Communicator::world();
    if (!comm.root()) {  // (at the descriptors: the interrupt handler writes to fd 2 itself)
      error_fd = ::dup(2);
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0) ::dup2(null, 1), ::dup2(null, 2), ::close(null);
    }
    Options o;
    auto tool = std::make_unique<cli::Tool>(
        "lbflow", "Stokes flow through the pore space by the D3Q19 lattice Boltzmann method (thesis 5.2.3): "
                  "permeability and hydraulic tortuosity, one CSV row per input on stdout, a summary line per input on "
                  "stderr (-q: none). Under mpirun or srun (mpirun -np 4 lbflow ...) one flow runs on all ranks, the "
                  "lattice cut into slabs along the flow axis, with the same results bit for bit; --threads is then "
                  "per rank.");
    declare(*tool, o);
    tool->parse(argc, argv);
    std::vector<std::string> args(argv + 1, argv + argc);
    if (o.list) {
      print_models();
      return 0;
    }
    if (!o.resume.empty() && o.inputs.empty()) {
      // `lbflow --resume FILE [options]`: the checkpoint's arguments, then the ones typed.
      auto stored = flowrun::read_checkpoint_args(o.resume);
      stored.insert(stored.end(), args.begin(), args.end());
      std::vector<char*> again{argv[0]};
      for (auto& a : stored) again.push_back(a.data());
      o = Options{};
      tool = std::make_unique<cli::Tool>(tool->name(), "");
      declare(*tool, o);
      tool->parse(static_cast<int>(again.size()), again.data());
      args = stored;
    }
    const auto plan = check(*tool, o, args);
    tool->finish_checks();
    cli::apply_threads(o.common);
    flowrun::FlowBatch batch{o.inputs,
                             {o.dims, plan.refinements.empty() ? 3 : plan.refinements.back(), o.delta, o.scale, o.d0, plan.run.flow.axis,
                              plan.run.flow.driving == lbm::Driving::kBodyForce},
                             plan.refinements, o.prolong, plan.run, plan.vtk_names, o.csv, o.history, o.timings, o.common.quiet,
                             o.drive == "force" ? "body-force" : "density-drop",
                             o.checkpoint.empty() ? "" : "; continue with lbflow --resume " + o.checkpoint + " --max-steps N"};
    batch.run.comm = comm;
    try {
      flowrun::run_flow_batch(batch, cli::provenance("lbflow", argc, argv));
    } catch (const std::exception& e) {
      // Met by this rank alone (not through agree): the others may be waiting for it in a
      // collective, so it names itself and ends them all rather than hang.
      if (!lbm::Communicator::error_agreed()) {
        const FailureReport report = failure_report(e);
        comm.abort_all(report.message, report.bad_input ? cli::kBadInput : cli::kComputationFailed, error_fd);
      }
      throw;
    }
    return 0;
  });
  // Every rank exits with the same status (the highest; an agreed error is said once, by rank 0).
  status = comm.max(status);  // (a collective: no rank leaves before all have their status)
  // mpirun ends the others when the first rank exits non-zero: past this point that is no
  // interruption (and rank 0's exit status is the one mpirun returns).
  std::signal(SIGTERM, SIG_IGN);
  lbm::Communicator::finalize();
  return status;
}
