#include "bench_mechanics_command.hpp"

#include "elasticity/benchmark_curves.hpp"
#include "io/atomic_output.hpp"
#include "shellbench/mechanics_benchmarks.hpp"

#include <iostream>

namespace cmp::shellpack {

CLI::App* BenchMechanicsCommand::add(cli::Tool& tool, CLI::App& parent, cli::CommonOptions& common) {
  auto* bench = parent.add_subcommand("bench-mechanics", "an Appendix B benchmark as CSV, computed beside the analytic curve");
  bench->add_option("case", case_, "sphere, poisson, plate-point, plate-uniform, plate-large, plates-contact or buckling")
      ->required();
  bench->add_flag("--analytic", analytic_, "write the analytic reference curve of the case instead (lib/elasticity)");
  bench->add_flag("--full", full_, "the thesis's mesh sizes and every load (slower; the figures)");
  tool.add_output(*bench, "-o,--output", output_, "CSV ('-': stdout)");
  tool.add_common(*bench, common, cli::Tool::kThreads | cli::Tool::kQuiet);
  return bench;
}

void BenchMechanicsCommand::check(cli::Tool& tool) {
  tool.collect("case", [&] { shellbench::check_mechanics_benchmark(case_); });
}

void BenchMechanicsCommand::run(bool quiet, const std::string& provenance) {
  io::AtomicOutput out(output_);
  if (analytic_)
    elasticity::write_csv(out.stream(), elasticity::analytic_curve(case_));
  else
    shellbench::run_mechanics_benchmark(case_, !full_, out.stream(), provenance, [&](const std::string& note) {
      if (!quiet) std::cerr << "shellpack: " << note << "\n";
    });
  out.commit();
}

}  // namespace cmp::shellpack
