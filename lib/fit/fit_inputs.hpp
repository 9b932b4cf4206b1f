#pragma once
// What kcfit fits from its rows (selection.hpp): the x, y and sigma columns (the option's, else
// the model's defaults), the loss when --loss is auto, and whether the rows mix systems that
// should be fitted apart.
#include "fit/fit.hpp"
#include "fit/selection.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace cmp::fit {

// The column named by the option (given non-empty; flag, e.g. "--x", named in the message),
// else the first of the model's defaults present. Throws cmp::InputError(first file, header
// line, "no column 'd1' (nor 'd2', ...: the default --x of model m; name one with --x)...")
// when none is.
int resolve_column(const Rows& rows, const std::string& given, const std::vector<std::string>& defaults,
                   const std::string& flag, const std::string& model);

// The loss of --loss option: parse_loss(option), or for "auto" maximum likelihood when the
// model is a probability and every selected y is 0 or 1, else linear. Reads the y cells of the
// selected rows up to the first that is neither 0 nor 1 whatever the option (cmp::InputError
// for a cell that is not a number).
Loss choose_loss(const std::string& option, const Model& model, const Rows& rows,
                 const std::vector<std::size_t>& selected, int y);

// The y cells of the selected rows as the model reads them: in a column of 0/1 outcomes
// (model.outcome_columns, the sigmoid's percolates) every value must be 0 or 1, and a
// probability model's y must lie in [0, 1]. Throws cmp::InputError(file, line, "percolates
// holds 0/1 outcomes (model sigmoid), got 2") at the first that does not.
void check_outcomes(const Model& model, const Rows& rows, const std::vector<std::size_t>& selected, int y);

// The column of the standard errors of y, or -1 for none: --sigma option (rows.column, an
// InputError naming --sigma when missing); "none": -1; not given: the column "<y_name>_error"
// when there is one and the loss is linear.
int sigma_column(const Rows& rows, const std::string& option, Loss loss, const std::string& y_name);

// One message per column among "delta" and "particles" (not the x or y column) with more than
// one value among the selected rows: different voxel sides or particle numbers are different
// systems, fitted as one set. "the data hold 2 values of delta (0.04 ... 0.05), fitted as one
// set; fit each with --group-by delta or --where delta=VALUE".
std::vector<std::string> mixed_systems(const Rows& rows, const std::vector<std::size_t>& selected, int x, int y);

}  // namespace cmp::fit
