#pragma once
// Independent jobs (files, seeds, packings) on all OpenMP threads, with the error handling a
// batch tool needs: an exception inside a job is kept, every job still runs, and afterwards
// the exception of the lowest-numbered failed job is rethrown, so the error a user sees does
// not depend on the thread count or on timing.
#include <exception>
#include <vector>

namespace cmp {

// Calls job(k) for k = 0 .. count-1 in parallel (dynamic schedule).
template <class Job>
void parallel_for_each_job(long count, Job&& job) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
#pragma omp parallel for schedule(dynamic)
  for (long k = 0; k < count; ++k) {
    try {
      job(k);
    } catch (...) {
      errors[static_cast<std::size_t>(k)] = std::current_exception();
    }
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace cmp
