#include "core/errors.hpp"
#include "core/parallel_for.hpp"

#include <catch2/catch.hpp>

#include <omp.h>

#include <atomic>

using namespace cmp;

TEST_CASE("parallel_for_each_job runs every job and rethrows the first failure by index", "[core]") {
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::atomic<long> ran{0};
    try {
      parallel_for_each_job(50, [&](long k) {
        ++ran;
        if (k == 31 || k == 7) throw InputError("job" + std::to_string(k), 0, "bad");
      });
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(e.file() == "job7");
    }
    CHECK(ran == 50);
  }
  std::vector<long> out(10);
  parallel_for_each_job(10, [&](long k) { out[k] = k * k; });
  CHECK(out[9] == 81);
}
