#include "analyze_command.hpp"

#include "spheres/structure.hpp"

#include <fmt/format.h>

namespace cmp::shellpack {

CLI::App* AnalyzeCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  auto& an = batch_;
  auto* analyze = parent.add_subcommand("analyze", "the Chapter 4 observables of packings of shells (packing OFFs): Z, g(r), "
                                                   "shapes, turgor, contact forces, mu_eff, walls, Voronoi facets");
  analyze->add_option("packings", an.inputs, "packing OFFs ('-': stdin); one summary row each")->required();
  tool.declare_inputs(*analyze, an.inputs);
  tool.add_output(*analyze, "-o,--output", an.output, "summary CSV, one row per packing ('-': stdout)");
  tool.add_output(*analyze, "--rdf", an.rdf_output, "write g(r) of the shell centres per packing to this CSV");
  tool.add_output(*analyze, "--shells", an.shells_output, "write one row per shell to this CSV");
  tool.add_output(*analyze, "--contacts", an.contacts_output, "write one row per contact and direction to this CSV");
  E_opt_ = tool.add_double(*analyze, "-E,--youngs-modulus", E_, "Young's modulus E [P] (default: the file's E=)",
                           cli::positive())->default_str("");
  nu_opt_ = tool.add_double(*analyze, "--nu,--poisson-ratio", nu_, "Poisson's ratio nu (default: the file's nu=, else 0.5)",
                            cli::left_open(-1, 0.5));
  rv_opt_ = tool.add_double(*analyze, "--vertex-radius", rv_,
                            "Hertz vertex radius R_v [u] (default: the file's vertex_radius=, else thickness=)",
                            cli::positive())
                ->default_str("");
  contact_opt_ = analyze->add_option("--contact", contact_,
                                     "contact law between shells: hertz-vertices or hertz-faces (default: the file's "
                                     "contact=, else hertz-vertices)");
  delta_opt_ = tool.add_double(*analyze, "--contact-distance", delta_,
                               "hertz-faces: contact distance delta [u] (default: the file's contact_distance=, else "
                               "thickness=)",
                               cli::positive())
                   ->default_str("");
  d0_opt_ = tool.add_double(*analyze, "--d0", d0_, "D0, the unit of g(r) [u] (default: the file's D0=, else from the volumes)",
                            cli::positive())->default_str("");
  p0_opt_ = tool.add_double(*analyze, "--p0", p0_, "initial turgor P0 [P] (default: the file's P0=)", cli::positive())
                ->default_str("");
  tool.add_double(*analyze, "--wall-modulus", an.options.wall_modulus, "Young's modulus of the walls [P] (default: rigid)",
                  cli::positive());
  tool.add_double(*analyze, "--bin", an.options.bin_width, "g(r) bin width [D0]", cli::positive());
  tool.add_double(*analyze, "--rmax", an.options.r_max, "g(r) range [D0]", cli::positive());
  tool.add_common(*analyze, common, cli::Tool::kThreads | cli::Tool::kQuiet);
  return analyze;
}

void AnalyzeCommand::check(cli::Tool& tool) {
  const auto& b = batch_;
  tool.check(b.options.r_max > b.options.bin_width, "--rmax", "must exceed --bin");
  tool.check(b.options.r_max / b.options.bin_width <= spheres::kMaxRdfBins,
             b.options.bin_width < packrun::AnalyzeBatch{}.options.bin_width ? "--bin" : "--rmax",
             fmt::format("--rmax / --bin makes {:.3g} bins of g(r), more than {:g}", b.options.r_max / b.options.bin_width,
                         spheres::kMaxRdfBins));
  const int to_stdout =
      (b.output == "-") + (b.rdf_output == "-") + (b.shells_output == "-") + (b.contacts_output == "-");
  tool.check(to_stdout <= 1, "", "-o, --rdf, --shells and --contacts: at most one of them may be '-' (stdout)");
  tool.check(!contact_opt_->count() || contact_ == "hertz-vertices" || contact_ == "hertz-faces", "--contact",
             "must be hertz-vertices or hertz-faces, got '" + contact_ + "'");
}

void AnalyzeCommand::run(bool quiet, const std::string& provenance) {
  auto& o = batch_.options;
  if (E_opt_->count()) o.youngs_modulus = E_;
  if (nu_opt_->count()) o.poisson_ratio = nu_;
  if (rv_opt_->count()) o.vertex_radius = rv_;
  if (delta_opt_->count()) o.contact_distance = delta_;
  if (contact_opt_->count()) o.contact = contact_;
  if (d0_opt_->count()) o.d0 = d0_;
  if (p0_opt_->count()) o.p0 = p0_;
  batch_.quiet = quiet;
  packrun::run_analyze_batch(batch_, provenance);
}

}  // namespace cmp::shellpack
