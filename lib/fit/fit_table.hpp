#pragma once
// kcfit's result tables (CSV, io::CsvWriter):
// - one fit: one row per parameter, `parameter,value,stderr,fixed,cov_<p1>,...` (and the
//   bootstrap's mean, standard deviation and 2.5/97.5 % quantiles), the fit's statistics as
//   `# key=value` lines above the header;
// - one fit per group (--group-by): one row per group, the group columns first, then n and
//   dropped, each parameter and its error (`phi_c,phi_c_error,...`, and with the bootstrap
//   `phi_c_bootstrap_stderr,phi_c_bootstrap_q025,phi_c_bootstrap_q975`), the goodness measures
//   and at_bound, so the table is the input of the next fit (the threshold law on phi_c).
// Goodness: maximum likelihood gives log_likelihood, null_log_likelihood, deviance and
// pseudo_r2 (McFadden); least squares r2 and chi2_dof; both aic.
#include "fit/bootstrap.hpp"
#include "fit/fit.hpp"
#include "io/csv.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cmp::fit {

// The goodness-of-fit measures of the fit's loss, as (name, formatted value); every one finite
// (fit() refuses others), but for a perfect fit's AIC (rss 0), which is left empty.
std::vector<std::pair<std::string, std::string>> goodness(const FitResult& r);

// "# key=value" lines of one fit (n, dropped, status, starts, goodness ...), then the
// per-parameter rows. boot may be null.
void write_parameter_table(io::CsvWriter& csv, const FitResult& r, const BootstrapResult* boot);

struct GroupFit {
  std::vector<std::string> key;  // formatted values of the group columns
  FitResult result;
  BootstrapResult boot;          // replicas == 0: none
};

// The header and one row per group; every fit of one model and loss.
void write_group_table(io::CsvWriter& csv, const std::vector<std::string>& group_columns,
                       const std::vector<GroupFit>& fits);

}  // namespace cmp::fit
