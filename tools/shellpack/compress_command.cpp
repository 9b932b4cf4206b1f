#include "compress_command.hpp"

#include "shell/styles.hpp"

#include "cli/checkpoint_args.hpp"

#include <cmath>

namespace cmp::shellpack {

namespace {

// The options that only steer this process, left out of a checkpoint's arguments.
constexpr cli::ProcessOnlyOption kProcessOnly[] = {
    {"--threads", true}, {"--resume", true}, {"--stop-after-steps", true}, {"-q", false}, {"--quiet", false}};

}  // namespace

std::vector<std::string> with_checkpoint_args(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  if (argc < 2 || args[1] != "compress") return args;
  std::string resume;
  for (int k = 2; k < argc; ++k) {
    if (args[k] == "--resume" && k + 1 < argc) resume = args[k + 1];
    if (args[k].starts_with("--resume=")) resume = args[k].substr(9);
  }
  if (resume.empty()) return args;
  const auto stored = packrun::compress_checkpoint_args(resume);
  std::vector<std::string> out{args[0], args[1]};
  out.insert(out.end(), stored.begin(), stored.end());
  out.insert(out.end(), args.begin() + 2, args.end());
  return out;
}

void CompressCommand::check(cli::Tool& tool) {
  const cli::CommonOptions& common = *common_;
  const std::vector<std::string>& args = args_;
  auto& m = job.run.model;
  tool.check(!job.packing_path.empty(), "packing", "is required (a jammed sphere packing, or --resume)");
  tool.check(!job.mesh_path.empty(), "--mesh", "is required");
  tool.check(job.run.between_tolerance == 0 || job.run.between_tolerance >= job.run.relax.relative_tolerance,
             "--ftol-between", "must be 0 (off) or at least --ftol");
  tool.check(!phi.empty() || !dphi.empty(), "--phi", "is required (or --dphi)");
  tool.check(phi.empty() || dphi.empty(), "--dphi", "cannot be combined with --phi");
  if (!phi.empty()) tool.collect("--phi", [&] { job.run.targets = packrun::parse_phi_targets(phi); });
  if (!dphi.empty())
    tool.collect("--dphi", [&] {
      job.run.targets = packrun::parse_phi_targets(dphi);
      job.run.targets_relative = true;
    });
  tool.check(job.run.targets.size() <= 1 || job.output_pattern.empty() ||
                 job.output_pattern.find("{phi}") != std::string::npos,
             "-o", "must contain {phi} when --phi names several targets, e.g. -o 'pack_{phi}.off'");
  tool.check(job.output_pattern != "-" || job.csv != "-", "--csv", "the packing already goes to stdout (-o -): write the CSV to a file");
  tool.collect("--model", [&] { shell::stretching_style(m.stretching); });
  if (m.bending == "none") m.bending.clear();
  if (!m.bending.empty()) tool.collect("--bending", [&] { shell::bending_style(m.bending); });
  volume_rule.apply(tool, job.run.relax);
  tool.check(m.pressure == "volume" || m.pressure == "turgor", "--pressure-model",
             "must be volume (constant volume) or turgor (constant Pi), got '" + m.pressure + "'");
  tool.check(m.shell_contact_style == "hertz-faces" || m.shell_contact_style == "hertz-vertices", "--contact",
             "must be hertz-faces (vertices against the other shells' triangles) or hertz-vertices (vertex spheres), got '" +
                 m.shell_contact_style + "'");
  tool.check(job.contact_distance == 0 || m.shell_contact_style == "hertz-faces", "--contact-distance",
             "needs --contact hertz-faces");
  if (job.run.walls) {
    tool.check(job.run.phi_start > 0 && job.run.phi_start < 1, "--phi-start",
               "must lie in (0, 1) (the dilute start of the walled box, e.g. 0.08)");
    tool.check(job.run.targets.empty() || job.run.targets.front() > job.run.phi_start, "--phi",
               "the targets must lie above --phi-start");
    m.contact.wall_modulus = wall_modulus * m.material.youngs_modulus;
  } else {
    tool.check(std::isinf(wall_modulus), "--wall-modulus", "needs --walls");
  }
  tool.check(job.resume.empty() || !job.checkpoint.empty(), "--resume",
             "needs the checkpoint's --checkpoint (kept in the file's arguments)");
  job.run.turgor0 = p0 * m.material.youngs_modulus;
  job.check_penetration = !no_penetration_check;
  job.seed = common.seed;
  job.quiet = common.quiet;
  // What a checkpoint records: the arguments after the subcommand.
  if (args.size() > 2) job.checkpoint_args = cli::checkpoint_arguments(std::span(args).subspan(2), kProcessOnly);
}

CLI::App* CompressCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  common_ = &common;
  auto& cm = job.run.model;
  cm.pressure = "volume";
  cm.material.youngs_modulus = 1.0;
  cm.material.poisson_ratio = 0.5;
  cm.material.thickness = 0.02;
  // The face barrier covers every point of the surface: it holds towards confluence (phi 0.95
  // on 642 and 2,562 vertices), where vertex spheres let vertices through the triangles.
  cm.shell_contact_style = "hertz-faces";
  job.run.relax.relative_tolerance = 1e-5;
  job.run.relax.fire.max_iterations = 200000;
  // Pi moves inside FIRE (every 20 iterations near convergence): near confluence a step takes
  // hundreds of updates (139 at phi = 0.85 on 16 x 642 shells).
  job.run.relax.max_volume_updates = 5000;
  auto* cp = parent.add_subcommand("compress", "pressurised elastic shells from a jammed sphere packing, compressed in a "
                                             "periodic box towards confluence (5.2.1, Ch. 4); CSV row per box step");
  // A resumed run repeats the checkpoint's arguments, then the ones typed: the last wins.
  cp->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  cp->add_option("packing", job.packing_path, "jammed sphere packing, extended XYZ (shellpack jam; first frame; periodic)");
  cp->add_option("--mesh", job.mesh_path, "the cell: closed, outward-oriented triangle mesh (OFF), one copy per sphere");
  tool.declare_input(*cp, job.packing_path);
  tool.declare_input(*cp, job.mesh_path);
  cp->add_option("--phi", phi, "target volume fractions, START:STOP:STEP or a list a,b,c (each in (0, 1])");
  cp->add_option("--dphi", dphi,
                 "targets as dphi = phi - phi_J above the inflated start instead (same forms; phi_J + dphi rounded to 6 decimals)");
  tool.add_output(*cp, "-o,--output", job.output_pattern, "write the packing OFF at each target here ({phi} = the target)");
  tool.add_output(*cp, "--csv", job.csv, "the table of box steps ('-': stdout)")->default_str("-");
  tool.add_double(*cp, "--step", job.run.step, "largest change of the box side per step [D0]", cli::positive());
  tool.add_double(*cp, "--P0", p0, "turgor Pi_0 of the inflated start [E]", cli::positive());
  tool.add_double(*cp, "-E,--youngs-modulus", cm.material.youngs_modulus, "Young's modulus E (the pressure unit)",
                  cli::positive());
  tool.add_double(*cp, "--nu,--poisson-ratio", cm.material.poisson_ratio, "Poisson's ratio nu", cli::left_open(-1, 0.5));
  tool.add_double(*cp, "-t,--thickness", cm.material.thickness, "wall thickness t [D0]", cli::positive());
  cp->add_option("--model", cm.stretching, "stretching model (shellpack shell --list-models)")->default_str("svk");
  cp->add_option("--bending", cm.bending, "bending model, or none (a membrane)")->default_str("none");
  cp->add_option("--pressure-model", cm.pressure, "volume (incompressible fill: Pi updated until every shell is "
                                                  "within 0.1 % of V0) or turgor (Pi = Pi_0 fixed)")
      ->default_str("volume");
  cp->add_flag("--walls", job.run.walls,
               "rigid box (Fig. 4.5): start dilute at --phi-start, walls on all six faces sweep the shells inward");
  tool.add_double(*cp, "--phi-start", job.run.phi_start, "--walls: the starting volume fraction (below the jammed one)");
  tool.add_double(*cp, "--wall-modulus", wall_modulus, "--walls: Young's modulus of the walls [E] (default rigid)",
                  cli::positive());
  cp->add_option("--contact", cm.shell_contact_style,
                 "contacts between shells: hertz-faces (every vertex against the other shells' triangles within "
                 "--contact-distance) or hertz-vertices (vertex spheres of radius --vertex-radius)")
      ->default_str(cm.shell_contact_style);
  tool.add_double(*cp, "--contact-distance", job.contact_distance,
                  "hertz-faces: the distance delta between touching mid-surfaces [D0] (0: t)", cli::non_negative());
  tool.add_double(*cp, "--vertex-radius", job.vertex_radius,
                  "Hertz vertex radius R_v [D0] of hertz-vertices and of the walls (0: t, or 0.75 x the largest "
                  "triangle circumradius if larger)",
                  cli::non_negative());
  tool.add_double(*cp, "--ftol", job.run.relax.relative_tolerance,
                  "FIRE stops when max_i |f_i| <= this * E t a (a: mean rest edge length)", cli::positive());
  tool.add_double(*cp, "--ftol-between", job.run.between_tolerance,
                  "FIRE tolerance of the box steps between targets, at least --ftol (0: --ftol); the targets keep "
                  "--ftol", cli::non_negative());
  tool.add_long(*cp, "--fire-max-iterations", job.run.relax.fire.max_iterations,
                "FIRE iteration cap per relaxation (exit 1 when reached)", cli::at_least(1));
  volume_rule.add(*cp);
  tool.add_int(*cp, "--max-volume-updates", job.run.relax.max_volume_updates,
               "Pi updates of the constant-volume loop per step before giving up (exit 1)", cli::at_least(1));
  tool.add_output(*cp, "--checkpoint", job.checkpoint, "save the run here every --checkpoint-every seconds and at the end");
  tool.add_double(*cp, "--checkpoint-every", job.checkpoint_every, "seconds between checkpoints", cli::non_negative());
  cp->add_option("--resume", job.resume, "continue the run saved in this checkpoint (alone: with its arguments)");
  tool.add_long(*cp, "--stop-after-steps", job.stop_after_steps,
                "stop after this many box steps (checkpoint and table so far; for tests)", cli::non_negative());
  cp->add_flag("--no-penetration-check", no_penetration_check,
               "skip the check, after every step, that no vertex lies inside another shell");
  cp->add_flag("--timings", job.timings, "add the wall time of each step (`seconds`) to the CSV");
  tool.add_common(*cp, common, cli::Tool::kSeed | cli::Tool::kThreads | cli::Tool::kQuiet);
  return cp;
}

void CompressCommand::run(bool, const std::string&) {
  // The run as the checkpoint records it (without --resume, --threads, ...): an interrupted
  // and resumed run then writes the same provenance, so the same bytes, as one never stopped.
  std::vector<std::string> run_args{"shellpack", "compress"};
  run_args.insert(run_args.end(), job.checkpoint_args.begin(), job.checkpoint_args.end());
  packrun::run_compress_job(job, cli::provenance("shellpack", run_args));
}

}  // namespace cmp::shellpack
