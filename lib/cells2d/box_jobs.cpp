#include "cells2d/box_jobs.hpp"

#include "cells2d/moduli.hpp"
#include "cells2d/packing_xyz.hpp"
#include "cells2d/tables.hpp"
#include "cli/progress.hpp"
#include "core/parallel_for.hpp"
#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/xyz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <iostream>
#include <memory>

namespace cmp::cells2d {

namespace {

std::vector<std::pair<std::string, std::string>> packing_info(const Colony& c, std::uint64_t seed, double dphi,
                                                              const std::string& provenance) {
  return {{"tool", provenance},
          {"seed", std::to_string(seed)},
          {"box", io::format_number(c.parameters().box)},
          {"cells", std::to_string(c.cells().size())},
          {"phi", io::format_number(c.area_fraction())},
          {"phi_J", io::format_number(c.phi_jamming())},
          {"dphi", io::format_number(dphi)},
          {"P0", io::format_number(c.parameters().P0)},
          {"time", io::format_number(c.time())},
          {"units", "sigma,k"}};
}


}  // namespace

void run_grow_job(const GrowJob& o) {
  std::unique_ptr<io::AtomicOutput> csv, packing, trajectory;
  if (!o.csv.empty()) csv = std::make_unique<io::AtomicOutput>(o.csv);
  if (!o.packing.empty()) packing = std::make_unique<io::AtomicOutput>(o.packing);
  if (!o.trajectory.empty()) trajectory = std::make_unique<io::AtomicOutput>(o.trajectory);
  std::unique_ptr<io::CsvWriter> table;
  if (csv) {
    table = std::make_unique<io::CsvWriter>(csv->stream());
    table->allow_infinity();  // P0 = inf: no feedback
    table->meta("provenance", o.provenance);
    table->meta("units", kUnits);
    table->meta("box", io::format_number(o.growth.box));
    table->meta("seed", std::to_string(o.seed));
    table->meta("P0", io::format_number(o.growth.P0));
    table->header(growth_columns());
  }
  std::unique_ptr<io::XyzWriter> frames;
  if (trajectory) frames = std::make_unique<io::XyzWriter>(trajectory->stream());
  Colony colony(o.growth, o.seed);
  cli::ProgressBar bar("growing", 1.0, o.quiet);
  const auto observe = [&](const StepRecord& r) {
    if (table) table->row(growth_row(r));
    if (frames && r.step % o.every == 0)
      frames->write(packing_frame(colony.cells(), o.growth.box, r.packing,
                                  packing_info(colony, o.seed, o.dphi, o.provenance)));
    bar.set_note(fmt::format("{} cells, phi {:.4f}", r.packing->cells, r.packing->area_fraction));
    bar.update(std::min(0.99, r.packing->area_fraction / (0.84 + o.dphi)));
  };
  colony.grow_to_jamming(observe);
  if (o.dphi > 0) colony.grow_beyond(o.dphi, observe);
  bar.finish();
  const auto cells = canonical_cells(colony.cells(), o.growth.box);
  if (packing) {
    Domain d;
    d.lx = d.ly = o.growth.box;
    ContactEngine engine(d, contact_law(o.growth.contact));
    const PackingAnalysis a = analyse_packing(cells, engine);
    io::XyzWriter(packing->stream()).write(packing_frame(cells, o.growth.box, &a,
                                                         packing_info(colony, o.seed, o.dphi, o.provenance)));
  }
  io::commit_in_order({packing.get(), trajectory.get(), csv.get()});
  if (!o.quiet)
    std::cerr << fmt::format("jam2d: jammed at phi_J = {:.6f}; {} cells at phi = {:.6f}, t = {:.4f}/gamma0; {} steps "
                             "accepted, {} rejected, {} FIRE iterations\n",
                             colony.phi_jamming(), colony.cells().size(), colony.area_fraction(), colony.time(),
                             colony.counters().accepted, colony.counters().rejected, colony.counters().iterations);
}

void run_moduli_job(const ModuliJob& o) {
  std::vector<CellPacking> packings;
  std::vector<std::pair<std::string, int>> labels;
  for (const auto& path : o.inputs) {
    auto frames = read_packings(path);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      labels.emplace_back(path, static_cast<int>(f));
      packings.push_back(std::move(frames[f]));
    }
  }
  const ContactLawStyle& law = contact_law(o.contact);
  std::vector<Moduli> results(packings.size());
  parallel_for_each_job(static_cast<long>(packings.size()),
                        [&](long k) { results[k] = measure_moduli(packings[k].cells, packings[k].box, law); });
  io::AtomicOutput out(o.output);
  io::CsvWriter table(out.stream());
  table.meta("provenance", o.provenance);
  table.meta("units", kUnits);
  table.meta("contact", law.name);
  std::vector<std::string> columns = {"file", "frame"};
  for (const auto& c : packing_columns()) columns.push_back(c);
  table.header(columns);
  for (std::size_t k = 0; k < packings.size(); ++k) {
    std::vector<std::string> row = {io::csv_field(labels[k].first), std::to_string(labels[k].second)};
    for (auto& v : packing_row(results[k], packings[k].box)) row.push_back(v);
    table.row(row);
  }
  out.commit();
}

void run_sweep_job(const SweepJob& o) {
  io::AtomicOutput out(o.output);
  const long n = static_cast<long>(o.seeds.size());
  std::vector<std::vector<std::vector<std::string>>> rows(static_cast<std::size_t>(n));
  cli::ProgressBar bar("sweep", static_cast<double>(n), o.quiet);
  std::atomic<long> done{0};
  parallel_for_each_job(n, [&](long k) {
    rows[static_cast<std::size_t>(k)] = sweep_seed(o.seeds[static_cast<std::size_t>(k)], o.growth, o.dphis, o.P0s);
    bar.update(static_cast<double>(++done));
  });
  bar.finish();
  io::CsvWriter table(out.stream());
  table.allow_infinity();  // P0 = inf: no feedback
  table.meta("provenance", o.provenance);
  table.meta("units", kUnits);
  table.meta("box", io::format_number(o.growth.box));
  table.meta("contact", o.growth.contact);
  table.meta("adaptive_step", o.growth.adaptive_step ? "1" : "0");
  table.meta("step_after_acceptance", o.growth.reset_step ? "reset" : "double");
  table.header(sweep_columns());
  for (const auto& seed_rows : rows)
    for (const auto& r : seed_rows) table.row(r);
  out.commit();
}

}  // namespace cmp::cells2d
