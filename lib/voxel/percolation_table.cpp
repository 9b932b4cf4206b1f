#include "voxel/percolation_table.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace cmp::voxel {

namespace {

// The located message of an InputError without its "file:line: " prefix.
std::string bare_message(const InputError& e) {
  const std::string what = e.what(), name = e.file() == "-" ? "<stdin>" : e.file();
  const std::string prefix = e.line() > 0 ? name + ":" + std::to_string(e.line()) + ": " : name + ": ";
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

}  // namespace

PercolationTables read_percolation_tables(const std::vector<std::string>& paths, const std::string& porosity_column) {
  PercolationTables out;
  // What must be the same in every row binned together, with where it was first seen.
  struct Seen {
    std::string value, where;
  };
  std::map<std::string, Seen> same;
  auto require_same = [&](const std::string& what, const std::string& value, const std::string& path, long line) {
    const std::string where = fmt::format("{}:{}", path == "-" ? "<stdin>" : path, line);
    auto [it, fresh] = same.try_emplace(what, Seen{value, where});
    if (!fresh && it->second.value != value)
      throw InputError(path, line, fmt::format("{} '{}' differs from '{}' at {}: percolate sweep bins one kind of "
                                               "run at a time (run it per {})", what, value, it->second.value,
                                               it->second.where, what));
  };
  std::map<std::string, std::string> runs_seen;  // file, frame, scale, delta -> where
  const std::vector<std::string> required{"particles", "delta", porosity_column, "percolates"};
  for (const auto& path : paths) {
    io::CsvTable t;
    try {
      t = io::read_csv(path);
    } catch (const InputError& e) {
      throw InputError(e.file(), e.line(), "not a percolate CSV (" + bare_message(e) + "); give the CSV rows "
                                           "percolate writes (columns particles, delta, " + porosity_column +
                                           ", percolates)");
    }
    for (const auto& name : required)
      if (std::find(t.header.begin(), t.header.end(), name) == t.header.end())
        throw InputError(path, t.header_line, fmt::format("not a percolate CSV: no column '{}' (percolate sweep needs "
                                                          "particles, delta, {}, percolates)", name, porosity_column));
    auto optional_column = [&](const std::string& name) {
      const auto it = std::find(t.header.begin(), t.header.end(), name);
      return it == t.header.end() ? -1 : static_cast<int>(it - t.header.begin());
    };
    const int cn = t.column("particles"), cd = t.column("delta"), cp = t.column(porosity_column),
              cy = t.column("percolates");
    for (const char* key : {"connectivity", "labelling"})
      if (const auto* v = t.find_meta(key)) require_same(key, *v, path, 1);
    const int cfile = optional_column("file"), cframe = optional_column("frame"), cscale = optional_column("scale");
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const long line = t.row_lines[r];
      for (const char* key : {"kind", "marking", "flow_axis", "porosity_method"})
        if (const int c = optional_column(key); c >= 0) require_same(key, t.rows[r][c], path, line);
      PercolationSample s;
      s.particles = static_cast<int>(io::parse_integer(t.rows[r][cn], path, line, "a particle count (particles)", 1,
                                                       std::numeric_limits<int>::max()));
      s.delta = t.number(r, cd);
      s.porosity = t.number(r, cp);
      s.percolates = io::parse_integer(t.rows[r][cy], path, line, "0 or 1 (percolates)", 0, 1) == 1;
      if (cscale >= 0) out.scales.insert(io::format_number(t.number(r, cscale)));
      if (cfile >= 0) {
        const std::string key = t.rows[r][cfile] + "\n" + (cframe >= 0 ? t.rows[r][cframe] : "") + "\n" +
                                (cscale >= 0 ? t.rows[r][cscale] : "") + "\n" +
                                io::format_number(s.delta);
        const std::string where = fmt::format("{}:{}", path == "-" ? "<stdin>" : path, line);
        auto [it, fresh] = runs_seen.try_emplace(key, where);
        if (!fresh)
          throw InputError(path, line, fmt::format("the run of {} at scale {} and delta {} is also at {}: a table "
                                                   "given twice?", t.rows[r][cfile],
                                                   cscale >= 0 ? t.rows[r][cscale] : "?", t.rows[r][cd], it->second));
      }
      out.samples.push_back(s);
    }
  }
  for (const auto& [key, seen] : same) out.same.emplace(key, seen.value);
  return out;
}

}  // namespace cmp::voxel
