#pragma once
// The fit of one group of rows (selection.hpp's Group; all selected rows without --group-by):
// its points and standard errors read from the rows, the fit, and its bootstrap.
#include "fit/fit.hpp"
#include "fit/fit_table.hpp"
#include "fit/selection.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cmp::fit {

struct GroupData {
  std::vector<double> x, y, sigma;  // sigma: empty when unweighted
  std::string sigma_column;         // its column, "" when unweighted
  long sigma_zero = 0;              // zero errors replaced by the group's smallest positive one
  std::string files;                // the files its rows come from, ", " between them
  std::string x_column, y_column;   // the columns' names, for messages
};

// The points of the rows (indices into rows) from columns x and y, and the errors from column
// sigma (-1: none). A zero error (a bin where every packing percolates, or none) would weigh
// its point infinitely: it takes the smallest positive error of the group instead (every error
// 0: fit_group refuses). Throws cmp::InputError(file, line, ...) for a cell that is not a
// number, a y that is not 0 or 1 with the loss ml, or a negative error.
GroupData group_data(const Rows& rows, const std::vector<std::size_t>& indices, int x, int y, int sigma,
                     Loss loss);

// "delta=0.04,particles=50": the group columns and the formatted key.
std::string group_label(const std::vector<std::string>& columns, const std::vector<std::string>& key);

// fit() of the group's points with options and, when replicas > 0, bootstrap() with seed; the
// key formatted with io::format_number. Throws cmp::ComputationError when every error is 0
// ("every <sigma> is 0: no weights ...") or the fit or bootstrap fails, the message prefixed
// with group_label(columns, key) when there are group columns; data no fit can describe
// (fit::DegenerateFit: too few points, no spread in x or y) is bad input, cmp::InputError(the
// files, 0, "delta=0.04: no spread in y: all 4 points have y = 1 (x: porosity, y: permeability)").
GroupFit fit_group(const Model& model, const GroupData& data, const FitOptions& options, int replicas,
                   std::uint64_t seed, const std::vector<std::string>& columns, const std::vector<double>& key);

}  // namespace cmp::fit
