#include "fit/group_fit.hpp"

#include "core/errors.hpp"
#include "fit/bootstrap.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cmp::fit {

GroupData group_data(const Rows& rows, const std::vector<std::size_t>& indices, int x, int y, int sigma,
                     Loss loss) {
  GroupData d;
  if (sigma >= 0) d.sigma_column = rows.header[sigma];
  const std::string& y_name = rows.header[y];
  d.x_column = rows.header[x], d.y_column = y_name;
  std::vector<std::size_t> sources;
  for (std::size_t i : indices)
    if (std::find(sources.begin(), sources.end(), rows.source[i]) == sources.end()) sources.push_back(rows.source[i]);
  std::sort(sources.begin(), sources.end());
  for (std::size_t k : sources) d.files += (d.files.empty() ? "" : ", ") + rows.files[k];
  for (std::size_t i : indices) {
    d.x.push_back(rows.number(i, x)), d.y.push_back(rows.number(i, y));
    if (loss == Loss::MaxLikelihood && d.y.back() != 0 && d.y.back() != 1)
      throw InputError(rows.files[rows.source[i]], rows.lines[i],
                       fmt::format("--loss ml needs {} to be 0 or 1, got {}", y_name, d.y.back()));
    if (sigma < 0) continue;
    d.sigma.push_back(rows.number(i, sigma));
    if (d.sigma.back() < 0)
      throw InputError(rows.files[rows.source[i]], rows.lines[i],
                       fmt::format("{} (the standard error of {}) is negative: {}", d.sigma_column, y_name,
                                   d.sigma.back()));
  }
  double smallest = kInf;
  for (double s : d.sigma)
    if (s > 0) smallest = std::min(smallest, s);
  for (double& s : d.sigma)
    if (s == 0) s = smallest, ++d.sigma_zero;
  return d;
}

std::string group_label(const std::vector<std::string>& columns, const std::vector<std::string>& key) {
  std::string s;
  for (std::size_t k = 0; k < columns.size(); ++k) s += fmt::format("{}{}={}", k ? "," : "", columns[k], key[k]);
  return s;
}

GroupFit fit_group(const Model& model, const GroupData& data, const FitOptions& options, int replicas,
                   std::uint64_t seed, const std::vector<std::string>& columns, const std::vector<double>& key) {
  GroupFit gf;
  for (double k : key) gf.key.push_back(io::format_number(k));
  try {
    // Every error was 0: none positive to take their place.
    if (!data.sigma.empty() && data.sigma_zero == static_cast<long>(data.sigma.size()))
      throw ComputationError(
          fmt::format("every {} is 0: no weights (--sigma none fits unweighted)", data.sigma_column));
    gf.result = fit(model, data.x, data.y, options, data.sigma);
    if (replicas > 0) gf.boot = bootstrap(model, data.x, data.y, options, gf.result, replicas, seed, data.sigma);
  } catch (const DegenerateFit& e) {
    const std::string group = columns.empty() ? "" : group_label(columns, gf.key) + ": ";
    throw InputError(data.files, 0,
                     fmt::format("{}{} (x: {}, y: {})", group, e.what(), data.x_column, data.y_column));
  } catch (const ComputationError& e) {
    if (columns.empty()) throw;
    throw ComputationError(group_label(columns, gf.key) + ": " + e.what());
  }
  return gf;
}

}  // namespace cmp::fit
