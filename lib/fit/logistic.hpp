#pragma once
// Maximum-likelihood fit of the sigmoid P(x) = 1 / (1 + exp(-(x - phi_c) / width)) to 0/1
// outcomes (does a packing percolate?), which is logistic regression: with a + b t the
// log-odds on the standardised abscissa t = (x - mean) / sd, the log-likelihood is concave
// and Newton's method (with step halving) converges from a = b = 0. phi_c = mean - sd a / b,
// width = sd / b; their covariance is the inverse Fisher information carried over by the
// delta method (not rescaled: the binomial variance is known). Fixing phi_c or width fixes
// a linear combination of (a, b), which this solver does not do: it throws UsageError.
#include "fit/problem.hpp"

namespace cmp::fit {

// Throws cmp::ComputationError when the outcomes are all alike, perfectly separated (every
// 0 below every 1: the threshold is anywhere in a gap and the width is 0) or Newton's method
// does not converge.
Solution solve_logistic(const Problem& problem);

}  // namespace cmp::fit
