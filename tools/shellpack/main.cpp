// shellpack: packings of soft spheres and of elastic shells (thesis 5.5.1, Ch. 4, App. B). Each
// subcommand is one <name>_command file (options, checks, run); main wires them.
//   shellpack jam -N 50 --seed 7 -o jammed.xyz > jam.csv        one rattler-free jammed packing
//   shellpack jam -N 32 --seeds 1:100 > jam_stats.csv             many, in parallel
//   shellpack jam -N 20 -o - | shellpack structure -              the packing down a pipe (no CSV then)
//   shellpack structure jammed.xyz > rdf.csv                      g(r), Z, rattlers, contact forces
//   shellpack shell --mesh cell.off --model svk -E 25e6 --nu 0.333 -t 0.1 --pressure 2.5e5 -o inflated.off > inflate.csv
//   shellpack shell ... --walls 2.0 --squeeze 0.3 -o squeezed.off > plates.csv      one shell between two plates
//   shellpack analyze pack_*.off --rdf rdf.csv > structure.csv   Z, shapes, turgor, contact forces of shell packings
//   shellpack bench-mechanics sphere > sphere.csv                 the Appendix B benchmarks (Figs B.4-B.10)
//   shellpack compress jammed.xyz --mesh cell.off --phi 0.70:0.95:0.05 -o 'pack_{phi}.off' > compress.csv
//   shellpack compress --resume compress.chk > compress.csv         continue an interrupted compression
#include "cli/tool.hpp"

#include "analyze_command.hpp"
#include "bench_mechanics_command.hpp"
#include "compress_command.hpp"
#include "jam_command.hpp"
#include "shell_command.hpp"
#include "structure_command.hpp"

#include <array>
#include <vector>

using namespace cmp;

int main(int argc, char** argv) {
  return cli::run_tool("shellpack", [&] {
    cli::CommonOptions common;
    cli::Tool tool("shellpack", "Jammed packings of soft spheres, their structure, and pressurised elastic shells (thesis 5.5.1, Ch. 4, App. B).");
    auto* app = &tool.app();
    app->require_subcommand(1);
    tool.add_common(*app, common, cli::Tool::kQuiet);

    // A resumed compression parses its checkpoint's arguments, then the ones typed.
    const auto full_args = shellpack::with_checkpoint_args(argc, argv);
    shellpack::JamCommand jam;
    shellpack::StructureCommand structure;
    shellpack::ShellCommand shell;
    shellpack::AnalyzeCommand analyze;
    shellpack::BenchMechanicsCommand bench;
    shellpack::CompressCommand compress(full_args);
    const std::array<shellpack::Command*, 6> commands{&jam, &structure, &shell, &analyze, &bench, &compress};
    std::array<CLI::App*, 6> apps{};
    for (std::size_t k = 0; k < commands.size(); ++k) apps[k] = commands[k]->add(tool, *app, common);

    std::vector<char*> full_argv;
    for (const auto& a : full_args) full_argv.push_back(const_cast<char*>(a.c_str()));
    tool.parse(static_cast<int>(full_argv.size()), full_argv.data());
    for (std::size_t k = 0; k < commands.size(); ++k)
      if (apps[k]->parsed()) commands[k]->check(tool);
    tool.finish_checks();
    cli::apply_threads(common);

    const std::string provenance = cli::provenance("shellpack", argc, argv);
    for (std::size_t k = 0; k < commands.size(); ++k)
      if (apps[k]->parsed()) commands[k]->run(common.quiet, provenance);
    return 0;
  });
}
