#include "structure_command.hpp"

#include "spheres/structure.hpp"

#include <fmt/format.h>

namespace cmp::shellpack {

CLI::App* StructureCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  auto& b = batch_;
  auto* structure = parent.add_subcommand("structure", "g(r), contact number, rattlers and contact forces of sphere packings");
  structure->add_option("packings", b.inputs, "extended XYZ packings (radius column, periodic Lattice; '-': stdin); frames pooled")
      ->required();
  tool.declare_inputs(*structure, b.inputs);
  tool.add_output(*structure, "-o,--output", b.output, "g(r) CSV ('-': stdout)");
  tool.add_double(*structure, "--bin", b.bin_width, "g(r) bin width [mean diameters]", cli::positive());
  tool.add_double(*structure, "--rmax", b.r_max,
                  "g(r) range [mean diameters]; beyond half the box every periodic image counts", cli::positive());
  tool.add_output(*structure, "--forces", b.forces_output, "write the contact force distribution P(f/<f>) to this CSV");
  tool.add_int(*structure, "--force-bins", b.force_bins, "bins of the force distribution over [0, 4<f>)", cli::at_least(1));
  tool.add_output(*structure, "--summary", b.summary_output, "write one row per packing (Z, rattlers, pressure, force cv) to this CSV");
  tool.add_common(*structure, common, cli::Tool::kThreads | cli::Tool::kQuiet);
  return structure;
}

void StructureCommand::check(cli::Tool& tool) {
  const auto& b = batch_;
  tool.check(b.r_max > b.bin_width, "--rmax", "must exceed --bin");
  tool.check(b.r_max / b.bin_width <= spheres::kMaxRdfBins, b.bin_width < packrun::StructureBatch{}.bin_width ? "--bin" : "--rmax",
             fmt::format("--rmax / --bin makes {:.3g} bins of g(r), more than {:g}", b.r_max / b.bin_width,
                         spheres::kMaxRdfBins));
  const int to_stdout = (b.output == "-") + (b.forces_output == "-") + (b.summary_output == "-");
  tool.check(to_stdout <= 1, "", "-o, --forces and --summary: at most one of them may be '-' (stdout)");
}

void StructureCommand::run(bool quiet, const std::string& provenance) {
  batch_.quiet = quiet;
  packrun::run_structure_batch(batch_, provenance);
}

}  // namespace cmp::shellpack
