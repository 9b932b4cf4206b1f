#include "cells2d/chamber_job.hpp"

#include "cells2d/avalanches.hpp"
#include "cells2d/chamber_output.hpp"
#include "cells2d/tables.hpp"
#include "cli/progress.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"
#include "io/atomic_output.hpp"
#include "io/checkpoint_file.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"
#include "io/xyz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace cmp::cells2d {

namespace {

constexpr const char* kMagic = "jam2d chamber checkpoint 1";

// What must agree between a checkpoint and the run resuming it (--time may grow).
std::vector<std::pair<std::string, std::string>> run_identity(const ChamberJob& job) {
  auto id = chamber_info(job.parameters, job.seed);
  id.emplace_back("every", io::format_number(job.sample_every));
  id.emplace_back("frame_every", io::format_number(job.frame_every));
  id.emplace_back("csv", job.csv.empty() ? "0" : "1");
  id.emplace_back("trajectory", job.trajectory.empty() ? "0" : "1");
  id.emplace_back("version", version());
  return id;
}

// The state between rows: the run, the next row's index, and the text written so far.
struct Progress {
  long next_sample = 0;
  std::string provenance, csv, frames;
};

void save(const ChamberJob& job, const ChamberRun& run, const Progress& p) {
  io::CheckpointOutput out(job.checkpoint, kMagic, {});
  auto& s = out.stream();
  const auto id = run_identity(job);
  io::put(s, static_cast<std::uint64_t>(id.size()));
  for (const auto& [k, v] : id) io::put(s, k), io::put(s, v);
  io::put(s, p.next_sample);
  io::put(s, p.provenance), io::put(s, p.csv), io::put(s, p.frames);
  run.save(s);
  out.commit();
}

void load(const ChamberJob& job, ChamberRun& run, Progress& p) {
  std::ifstream in = io::open_checkpoint(job.resume);
  io::read_checkpoint_header(in, job.resume, kMagic, "a jam2d chamber checkpoint", true);
  io::CheckpointReader r(in, job.resume);
  const auto id = run_identity(job);
  const auto n = r.get<std::uint64_t>();
  if (n != id.size()) throw InputError(job.resume, 0, "not a checkpoint of this run (another version of jam2d?)");
  for (const auto& [key, value] : id) {
    const std::string k = r.get_string(256);
    const std::string v = r.get_string(1 << 20);
    if (k != key) throw InputError(job.resume, 0, "not a checkpoint of this run (another version of jam2d?)");
    if (v != value)
      throw InputError(job.resume, 0,
                       fmt::format("the checkpoint is of another run: {}={} there, {} here", key, v, value));
  }
  p.next_sample = r.get<long>();
  constexpr std::uint64_t kText = std::uint64_t{1} << 36;
  p.provenance = r.get_string(kText);
  p.csv = r.get_string(kText);
  p.frames = r.get_string(kText);
  run.load(r);
}

// The k-th row's time, k * every to 12 significant digits: rows every 0.1 read 4.6, not
// 4.6000000000000005 (the run itself steps to within dt of it).
double scheduled_time(long k, double every) {
  double t = 0;
  io::try_parse_double(fmt::format("{:.12g}", static_cast<double>(k) * every), t);
  return t;
}

}  // namespace

void run_chamber_job(const ChamberJob& job) {
  std::unique_ptr<io::AtomicOutput> csv, trajectory;
  if (!job.csv.empty()) csv = std::make_unique<io::AtomicOutput>(job.csv);
  if (!job.trajectory.empty()) trajectory = std::make_unique<io::AtomicOutput>(job.trajectory);
  const ChamberParameters& p = job.parameters;
  ChamberRun run(p, job.seed);
  Progress progress;
  progress.provenance = job.provenance;
  if (!job.resume.empty()) load(job, run, progress);

  // Rows and frames go to memory first: a checkpoint carries them, and the files appear whole
  // at the end.
  std::ostringstream rows, frames_text;
  rows << progress.csv;
  frames_text << progress.frames;
  io::CsvWriter table(rows);
  table.allow_infinity();  // P0 = inf: no feedback
  if (progress.next_sample == 0) {
    table.meta("provenance", progress.provenance);
    table.meta("units", kUnits);
    for (const auto& [k, v] : chamber_info(p, job.seed)) table.meta(k, v);
  }
  if (progress.next_sample == 0)
    table.header(chamber_columns());
  else
    table.header_written_before(chamber_columns());
  io::XyzWriter frames(frames_text);
  auto info = chamber_info(p, job.seed);
  info.insert(info.begin(), {"tool", progress.provenance});

  cli::ProgressBar bar("chamber", job.duration, job.quiet);
  const long samples = std::lround(job.duration / job.sample_every);
  const long frame_stride = std::max(1L, std::lround(job.frame_every / job.sample_every));
  using clock = std::chrono::steady_clock;
  auto last_save = clock::now();
  const auto checkpoint_now = [&](long next) {
    progress.next_sample = next;
    progress.csv = rows.str(), progress.frames = frames_text.str();
    save(job, run, progress);
    last_save = clock::now();
  };
  for (long k = progress.next_sample; k <= samples; ++k) {
    const double t = scheduled_time(k, job.sample_every);
    if (job.stop_after >= 0 && t > job.stop_after) {
      if (!job.checkpoint.empty()) checkpoint_now(k);
      bar.finish();
      if (!job.quiet)
        std::cerr << fmt::format("jam2d: stopped at t = {}/gamma0 as asked{}\n", io::format_number(run.time()),
                                 job.checkpoint.empty() ? "" : "; continue with --resume " + job.checkpoint);
      return;
    }
    run.advance_to(t);
    ChamberSample s = run.sample();
    s.time = t;  // the scheduled time, to within a step
    table.row(chamber_row(s));
    if (k % frame_stride == 0) frames.write(chamber_frame(run, info));
    bar.set_note(fmt::format("{} cells, P {:.3f} k, {} left", s.chamber_cells, s.pressure_walls, s.left));
    bar.update(run.time());
    if (!job.checkpoint.empty() && k < samples &&
        std::chrono::duration<double>(clock::now() - last_save).count() >= job.checkpoint_every)
      checkpoint_now(k + 1);
  }
  bar.finish();
  if (!job.checkpoint.empty()) checkpoint_now(samples + 1);
  if (trajectory) trajectory->stream() << frames_text.str();
  if (csv) csv->stream() << rows.str();
  io::commit_in_order({trajectory.get(), csv.get()});
  if (!job.quiet)
    std::cerr << fmt::format("jam2d: t = {}/gamma0 in {} steps (dt {}); {} cells, {} divisions, {} left; {} force "
                             "evaluations, {} neighbour-list builds\n",
                             io::format_number(run.time()), run.steps(), io::format_number(p.time_step()),
                             run.cells().size(), run.divisions(), run.left(), run.evaluations(), run.list_builds());
}

void run_avalanche_job(const AvalancheJob& o) {
  const io::CsvTable t = io::read_csv(o.input);
  const int time = t.column("time"), pressure = t.column(o.pressure_column), left = t.column("left");
  PressureSeries s;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    s.time.push_back(t.number(r, time));
    s.pressure.push_back(t.number(r, pressure));
    s.left.push_back(static_cast<long>(t.integer(r, left, 0, 1'000'000'000'000LL)));
    if (r > 0 && !(s.time[r] > s.time[r - 1]))
      throw InputError(t.file, t.row_lines[r], "time must increase from row to row");
    if (r > 0 && s.left[r] < s.left[r - 1])
      throw InputError(t.file, t.row_lines[r], "left (cells removed so far) must not decrease");
  }
  const std::vector<Avalanche> events = find_avalanches(s, o.merge, o.from);
  const AvalancheSummary m = summarise(s, events, o.from);
  std::unique_ptr<io::AtomicOutput> distribution;
  if (!o.distribution.empty()) distribution = std::make_unique<io::AtomicOutput>(o.distribution);
  io::AtomicOutput out(o.output);
  io::CsvWriter table(out.stream());
  const auto num = [](double v) { return io::format_number(v); };
  table.meta("provenance", o.provenance);
  table.meta("units", kUnits);
  table.meta("input", o.input);
  table.meta("pressure", o.pressure_column);
  if (const auto* seed = t.find_meta("seed")) table.meta("seed", *seed);
  for (const char* key : {"mobility", "P0", "outlet", "attraction"})
    if (const auto* v = t.find_meta(key)) table.meta(key, *v);
  const std::pair<const char*, std::string> summary[] = {
      {"from", num(m.from)},
      {"to", num(m.to)},
      {"mean_pressure", num(m.mean_pressure)},
      {"events", std::to_string(m.events)},
      {"mean_drop", num(m.mean_drop)},
      {"mean_size", num(m.mean_size)},
      {"mean_rise_rate", num(m.mean_rise_rate)},
      {"mean_drop_rate", num(m.mean_drop_rate)},
      {"drop_over_rise_rate", num(m.rate_ratio)},
      {"tail_events", std::to_string(m.tail_events)},
      {"tail_scale_over_mean_drop", num(m.tail_scale)},
      {"tail_ks_distance", num(m.tail_ks)}};
  for (const auto& [key, value] : summary) table.meta(key, value);
  table.header({"event", "start", "end", "peak_time", "peak", "base_time", "base", "drop", "rise_rate", "drop_rate",
                "cells"});
  for (std::size_t e = 0; e < events.size(); ++e) {
    const Avalanche& a = events[e];
    table.row({std::to_string(e), num(a.start), num(a.end), num(a.peak_time), num(a.peak), num(a.base_time),
               num(a.base), num(a.drop), num(a.rise_rate), num(a.drop_rate), std::to_string(a.size)});
  }
  if (distribution) {
    // The survival function of the drops in units of their mean (Fig. 2.2e) and the exponential
    // of the fitted tail.
    std::vector<double> drops;
    for (const Avalanche& a : events) drops.push_back(m.mean_drop > 0 ? a.drop / m.mean_drop : 0.0);
    std::sort(drops.begin(), drops.end());
    io::CsvWriter d(distribution->stream());
    d.meta("provenance", o.provenance);
    d.meta("input", o.input);
    d.meta("mean_drop", num(m.mean_drop));
    d.header({"drop_over_mean", "survival", "exponential_tail"});
    const double n = static_cast<double>(drops.size()), tail = static_cast<double>(m.tail_events) / std::max(1.0, n);
    for (std::size_t i = 0; i < drops.size(); ++i) {
      const double x = drops[i], model = x > 1 && m.tail_scale > 0 ? tail * std::exp(-(x - 1) / m.tail_scale) : 0.0;
      d.row({num(x), num(1 - static_cast<double>(i) / n), num(model)});
    }
  }
  io::commit_in_order({distribution.get(), &out});
}

}  // namespace cmp::cells2d
