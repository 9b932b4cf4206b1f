#include "shell_command.hpp"

#include "io/csv.hpp"
#include "shell/styles.hpp"

#include <cmath>
#include <iostream>

namespace cmp::shellpack {

CLI::App* ShellCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  auto& run = job_.run;
  auto& model = run.model;
  model.pressure = "turgor";
  auto* sh = parent.add_subcommand("shell", "one pressurised elastic shell on a triangle mesh, inflated and optionally "
                                            "squeezed between two plates (App. B); CSV row per load step");
  sh->add_option("--mesh", job_.mesh_path, "closed, outward-oriented triangle mesh (OFF; '-': stdin)");
  tool.declare_input(*sh, job_.mesh_path);
  sh->add_flag("--list-models", list_models_, "list the registered stretching, bending, pressure and contact models (CSV) and exit");
  sh->add_option("--model", model.stretching, "stretching model (--list-models)")->default_str("svk");
  sh->add_option("--bending", model.bending, "bending model, or none (a membrane)")->default_str("none");
  sh->add_option("--pressure-model", model.pressure, "turgor (constant Pi) or volume (inflate, then hold the volume)")
      ->default_str("turgor");
  tool.add_double(*sh, "-E,--youngs-modulus", model.material.youngs_modulus, "Young's modulus E [P: any pressure unit]",
                  cli::positive());
  tool.add_double(*sh, "--nu,--poisson-ratio", model.material.poisson_ratio, "Poisson's ratio nu",
                  cli::left_open(-1, 0.5));
  tool.add_double(*sh, "-t,--thickness", model.material.thickness, "wall thickness t [u: the mesh's length unit]",
                  cli::positive());
  tool.add_double(*sh, "--pressure", run.pressure, "turgor Pi to inflate to [P]");
  tool.add_int(*sh, "--steps", run.pressure_steps, "inflation load steps (one CSV row each)", cli::at_least(1));
  tool.add_double(*sh, "--walls", wall_gap_, "put two plates this far apart (normal z, centred on the mesh) [u]",
                  cli::non_negative());
  tool.add_double(*sh, "--squeeze", run.squeeze, "reduce the plate gap by this fraction after inflating",
                  cli::right_open(0, 1));
  tool.add_int(*sh, "--squeeze-steps", run.squeeze_steps, "squeeze steps (one CSV row each)", cli::at_least(1));
  tool.add_double(*sh, "--vertex-radius", vertex_radius_, "Hertz vertex radius R_v [u] (default: t)", cli::non_negative());
  tool.add_double(*sh, "--wall-modulus", model.contact.wall_modulus, "Young's modulus of the plates [P] (default: rigid)",
                  cli::positive());
  tool.add_double(*sh, "--ftol", run.relax.relative_tolerance,
                  "FIRE stops when max_i |f_i| <= this * E t a (a: mean rest edge length)", cli::positive());
  tool.add_long(*sh, "--fire-max-iterations", run.relax.fire.max_iterations, "FIRE iteration cap per relaxation",
                cli::at_least(1));
  volume_rule_.add(*sh);
  tool.add_output(*sh, "-o,--output", job_.mesh_output, "write the relaxed mesh to this OFF ('-': stdout)");
  tool.add_output(*sh, "--csv", job_.csv, "the table of load steps ('-': stdout)")->default_str("-");
  tool.add_common(*sh, common, cli::Tool::kThreads | cli::Tool::kQuiet);
  return sh;
}

void ShellCommand::check(cli::Tool& tool) {
  if (list_models_) return;
  tool.check(!job_.mesh_path.empty(), "--mesh", "is required (or --list-models)");
  auto& m = job_.run.model;
  tool.collect("--model", [&] { shell::stretching_style(m.stretching); });
  if (m.bending == "none") m.bending.clear();
  if (!m.bending.empty()) tool.collect("--bending", [&] { shell::bending_style(m.bending); });
  tool.collect("--pressure-model", [&] { shell::pressure_style(m.pressure); });
  volume_rule_.apply(tool, job_.run.relax);
  m.contact.vertex_radius = vertex_radius_ > 0 ? vertex_radius_ : m.material.thickness;
  m.contact.youngs_modulus = m.material.youngs_modulus;
  m.contact.poisson_ratio = m.material.poisson_ratio;
  if (wall_gap_ > 0) job_.run.wall_gap = wall_gap_;
  tool.check(job_.run.squeeze == 0 || job_.run.wall_gap.has_value(), "--squeeze", "needs --walls");
  // A turgor of the order of E strains the wall by Pi R / (2 E t), R/t times more than any
  // elastic law holds; 1e308 overflowed the stiffness estimate ("FIRE: mass must be positive").
  const double E = m.material.youngs_modulus;
  tool.check(!(E > 0) || std::abs(job_.run.pressure) <= E, "--pressure",
             "must be at most Young's modulus E = " + io::format_number(E) +
                 " in magnitude (the wall's strain Pi R / (2 E t) would exceed R / (2 t)), got '" +
                 io::format_number(job_.run.pressure) + "'");
  tool.check(!(job_.mesh_output == "-" && job_.csv == "-"), "--csv",
             "the mesh already goes to stdout (-o -): write the CSV to a file");
}

void ShellCommand::run(bool quiet, const std::string& provenance) {
  if (list_models_) {
    shell::write_model_list(std::cout);
    return;
  }
  job_.quiet = quiet;
  packrun::run_shell_job(job_, provenance);
}

}  // namespace cmp::shellpack
